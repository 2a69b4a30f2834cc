// Region growing and free space (bvb/region.h) on hand-made images, against an independent
// implementation of the definition, and free space against the scene renderer's column truth.
#include <gtest/gtest.h>

#include <cstdint>
#include <algorithm>
#include <cstdlib>
#include <deque>
#include <vector>

#include "bvb/region.h"
#include "scene/render.h"
#include "scene/world.h"

namespace {

struct Grown {
  std::vector<uint8_t> mask;
  bvb_region_stats st;
};

Grown grow(const std::vector<uint8_t> &img, int w, int h, int sx, int sy, int tol, int conn, int cap = -1) {
  Grown g;
  g.mask.assign(size_t(w) * h, 0x77);
  if (cap < 0) cap = w * h;
  std::vector<int32_t> q(size_t(cap) + 1);
  bvb_region_params p{sx, sy, tol, conn};
  const int32_t r = bvb_region_grow_c(img.data(), w, g.mask.data(), w, w, h, &p, q.data(), cap, &g.st);
  EXPECT_EQ(r, g.st.count);
  return g;
}

TEST(RegionGrow, FillsExactlyAConstantRectangle) {
  // A 9 x 7 rectangle of 120 (x 4..12, y 3..9) on a background of 50 and a ring of 135 that
  // touches it: tolerance 10 keeps the region inside, for either connectivity.
  const int w = 20, h = 15;
  std::vector<uint8_t> img(size_t(w) * h, 50);
  for (int y = 2; y <= 10; ++y)
    for (int x = 3; x <= 13; ++x) img[size_t(y) * w + x] = 135;
  for (int y = 3; y <= 9; ++y)
    for (int x = 4; x <= 12; ++x) img[size_t(y) * w + x] = 120;
  for (int conn : {4, 8}) {
    const Grown g = grow(img, w, h, 8, 6, 10, conn);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const bool in = x >= 4 && x <= 12 && y >= 3 && y <= 9;
        EXPECT_EQ(g.mask[size_t(y) * w + x], in ? 255 : 0) << "conn " << conn << " at " << x << "," << y;
      }
    EXPECT_EQ(g.st.count, 63);
    EXPECT_EQ(g.st.sum, 63 * 120);
    EXPECT_EQ(g.st.min_x, 4);
    EXPECT_EQ(g.st.max_x, 12);
    EXPECT_EQ(g.st.min_y, 3);
    EXPECT_EQ(g.st.max_y, 9);
    EXPECT_EQ(g.st.sum_x, (4 + 12) * 9 / 2 * 7);  // 72 per row, 7 rows
    EXPECT_EQ(g.st.sum_y, (3 + 9) * 7 / 2 * 9);   // 42 per column, 9 columns
    EXPECT_EQ(g.st.dropped, 0);
  }
}

TEST(RegionGrow, NoisyRampStopsWhereTheMeanDriftsPastTheTolerance) {
  // One row of a noisy upward ramp between rows of 0, seeded at its left end, tolerance 5.
  // By hand, with count/sum before each test and |I * count - sum| <= 5 * count:
  //   x=1  103: |103*1 - 100| =  3 <=  5  joins  (count 2, sum 203)
  //   x=2   99: | 99*2 - 203| =  5 <= 10  joins  (3, 302)
  //   x=3  104: |104*3 - 302| = 10 <= 15  joins  (4, 406)
  //   x=4  106: |106*4 - 406| = 18 <= 20  joins  (5, 512)
  //   x=5  105: |105*5 - 512| = 13 <= 25  joins  (6, 617)
  //   x=6  109: |109*6 - 617| = 37 >  30  stops: the mean (102.8) lags the ramp by more than 5,
  // although 109 is within 5 of its neighbour 105. Nothing past x = 5 can join.
  const int vals[] = {100, 103, 99, 104, 106, 105, 109, 111, 114, 112, 116, 118};
  const int w = 12, h = 3;
  std::vector<uint8_t> img(size_t(w) * h, 0);
  for (int x = 0; x < w; ++x) img[size_t(w) + x] = uint8_t(vals[x]);
  for (int conn : {4, 8}) {
    const Grown g = grow(img, w, h, 0, 1, 5, conn);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        EXPECT_EQ(g.mask[size_t(y) * w + x], y == 1 && x <= 5 ? 255 : 0) << "conn " << conn << " at " << x << "," << y;
    EXPECT_EQ(g.st.count, 6);
    EXPECT_EQ(g.st.sum, 617);
    EXPECT_EQ(g.st.sum_x, 0 + 1 + 2 + 3 + 4 + 5);
    EXPECT_EQ(g.st.sum_y, 6);
  }
}

TEST(RegionGrow, TheMeanMovesWithEveryPixelInVisitingOrder) {
  // 3 x 3, seed at the centre (100), tolerance 10, 4-connected; neighbours are tested left,
  // right, up, down. By hand:
  //   left  110: |110*1 - 100| = 10 <= 10 joins (2, 210)
  //   right  94: | 94*2 - 210| = 22 >  20 out   (though within 10 of the seed alone)
  //   up    115: |115*2 - 210| = 20 <= 20 joins (3, 325)   (though 15 from the seed)
  //   down   96: | 96*3 - 325| = 37 >  30 out
  //   from left (0,1): up (0,0) 112: |112*3 - 325| = 11 <= 30 joins (4, 437);
  //                    down (0,2) 90: |90*4 - 437| = 77 > 40 out
  //   from up (1,0):   right (2,0) 120: |120*4 - 437| = 43 > 40 out
  //   from (0,0): nothing new. Region: (0,0), (1,0), (0,1), (1,1).
  // With 8-connectivity the centre also tests its diagonals after the four, and (0,0) joins
  // from there; every other test still fails (94: 22 > 20; 96: 37 > 30; 120: 43 > 40;
  // 90: 77 > 40; 130: 83 > 40; 96 again from (0,1): |96*4 - 437| = 53 > 40;
  // 94 again from (1,0): |94*4 - 437| = 61 > 40), so the region is the same.
  const std::vector<uint8_t> img = {112, 115, 120,  //
                                    110, 100, 94,   //
                                    90,  96,  130};
  for (int conn : {4, 8}) {
    const Grown g = grow(img, 3, 3, 1, 1, 10, conn);
    const std::vector<uint8_t> want = {255, 255, 0, 255, 255, 0, 0, 0, 0};
    EXPECT_EQ(g.mask, want) << "conn " << conn;
    EXPECT_EQ(g.st.count, 4);
    EXPECT_EQ(g.st.sum, 437);
    EXPECT_EQ(g.st.min_x, 0);
    EXPECT_EQ(g.st.max_x, 1);
    EXPECT_EQ(g.st.min_y, 0);
    EXPECT_EQ(g.st.max_y, 1);
  }
}

TEST(RegionGrow, FullQueueKeepsThePixelButDoesNotExpandIt) {
  // A constant 5 x 1 row, seed x = 2, a queue of one entry. The seed is taken; its left
  // neighbour joins and is queued; its right neighbour joins while the queue is full (dropped,
  // never expanded), so x = 4 is never reached. Then x = 1 brings in x = 0.
  const std::vector<uint8_t> img(5, 77);
  const Grown g = grow(img, 5, 1, 2, 0, 0, 4, 1);
  EXPECT_EQ(g.mask, (std::vector<uint8_t>{255, 255, 255, 255, 0}));
  EXPECT_EQ(g.st.count, 4);
  EXPECT_EQ(g.st.dropped, 1);
  // No queue at all: the seed alone, itself dropped.
  const Grown g0 = grow(img, 5, 1, 2, 0, 0, 4, 0);
  EXPECT_EQ(g0.mask, (std::vector<uint8_t>{0, 0, 255, 0, 0}));
  EXPECT_EQ(g0.st.count, 1);
  EXPECT_EQ(g0.st.dropped, 1);
}

TEST(RegionGrow, SeedOutsideGivesAnEmptyRegion) {
  const std::vector<uint8_t> img(12, 9);
  for (auto [sx, sy] : {std::pair{-1, 0}, std::pair{4, 0}, std::pair{0, 3}, std::pair{2, -5}}) {
    const Grown g = grow(img, 4, 3, sx, sy, 255, 8);
    EXPECT_EQ(g.mask, std::vector<uint8_t>(12, 0));
    EXPECT_EQ(g.st.count, 0);
    EXPECT_EQ(g.st.sum, 0);
    EXPECT_EQ(g.st.min_x, 4);
    EXPECT_EQ(g.st.min_y, 3);
    EXPECT_EQ(g.st.max_x, -1);
    EXPECT_EQ(g.st.max_y, -1);
  }
}

// The definition, written again independently: a std::deque as the FIFO (bounded the same way),
// a separate visited map, 64-bit arithmetic and a real division-free test.
Grown grow_reference(const std::vector<uint8_t> &img, int w, int h, int sx, int sy, int tol, int conn, int cap) {
  Grown g;
  g.mask.assign(size_t(w) * h, 0);
  g.st = {0, 0, w, h, -1, -1, 0, 0, 0};
  if (sx < 0 || sy < 0 || sx >= w || sy >= h) return g;
  std::deque<std::pair<int, int>> q;
  int64_t count = 0, sum = 0;
  auto accept = [&](int x, int y) {
    g.mask[size_t(y) * w + x] = 255;
    ++count;
    sum += img[size_t(y) * w + x];
    g.st.sum_x += x, g.st.sum_y += y;
    g.st.min_x = std::min(g.st.min_x, x), g.st.max_x = std::max(g.st.max_x, x);
    g.st.min_y = std::min(g.st.min_y, y), g.st.max_y = std::max(g.st.max_y, y);
    if (int(q.size()) < cap)
      q.push_back({x, y});
    else
      ++g.st.dropped;
  };
  accept(sx, sy);
  const int dx[8] = {-1, 1, 0, 0, -1, 1, -1, 1}, dy[8] = {0, 0, -1, 1, -1, -1, 1, 1};
  while (!q.empty()) {
    auto [x, y] = q.front();
    q.pop_front();
    for (int k = 0; k < conn; ++k) {
      const int nx = x + dx[k], ny = y + dy[k];
      if (nx < 0 || ny < 0 || nx >= w || ny >= h || g.mask[size_t(ny) * w + nx]) continue;
      const int64_t i = img[size_t(ny) * w + nx];
      if (std::llabs(i * count - sum) <= int64_t(tol) * count) accept(nx, ny);
    }
  }
  g.st.count = int32_t(count);
  g.st.sum = int32_t(sum);
  return g;
}

TEST(RegionGrow, MatchesIndependentImplementation) {
  uint32_t s = 777;
  auto rnd = [&]() { return s = s * 1664525u + 1013904223u, s >> 8; };
  for (int trial = 0; trial < 200; ++trial) {
    const int w = 1 + int(rnd() % 40), h = 1 + int(rnd() % 30);
    std::vector<uint8_t> img(size_t(w) * h);
    // Smooth ramps plus noise plus blocks: regions that grow, drift and stop.
    const int base = int(rnd() % 200), gx = int(rnd() % 7) - 3, gy = int(rnd() % 7) - 3, noise = int(rnd() % 20);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        img[size_t(y) * w + x] = uint8_t(std::clamp(base + gx * x + gy * y + int(rnd() % (noise + 1)), 0, 255));
    for (int b = int(rnd() % 4); b > 0; --b) {
      const int bx = int(rnd() % w), by = int(rnd() % h), v = int(rnd() % 256);
      for (int y = by; y < std::min(h, by + 1 + int(rnd() % 10)); ++y)
        for (int x = bx; x < std::min(w, bx + 1 + int(rnd() % 10)); ++x) img[size_t(y) * w + x] = uint8_t(v);
    }
    const int sx = int(rnd() % w), sy = int(rnd() % h), tol = int(rnd() % 30), conn = rnd() % 2 ? 8 : 4;
    const int cap = rnd() % 3 == 0 ? int(rnd() % 6) : w * h;
    const Grown a = grow(img, w, h, sx, sy, tol, conn, cap);
    const Grown b = grow_reference(img, w, h, sx, sy, tol, conn, cap);
    ASSERT_EQ(a.mask, b.mask) << "trial " << trial;
    EXPECT_EQ(a.st.count, b.st.count);
    EXPECT_EQ(a.st.sum, b.st.sum);
    EXPECT_EQ(a.st.min_x, b.st.min_x);
    EXPECT_EQ(a.st.min_y, b.st.min_y);
    EXPECT_EQ(a.st.max_x, b.st.max_x);
    EXPECT_EQ(a.st.max_y, b.st.max_y);
    EXPECT_EQ(a.st.sum_x, b.st.sum_x);
    EXPECT_EQ(a.st.sum_y, b.st.sum_y);
    EXPECT_EQ(a.st.dropped, b.st.dropped);
  }
}

std::vector<int16_t> free_space(const std::vector<uint8_t> &mask, int w, int h, int min_gap) {
  std::vector<int16_t> rows(size_t(w), 12345);
  bvb_free_space_c(mask.data(), w, w, h, min_gap, rows.data());
  return rows;
}

TEST(FreeSpace, HandMadeColumns) {
  // Columns (# obstacle, . floor), 6 wide, 8 high, rows top to bottom:
  //   x0 all floor -> -1 whatever min_gap
  //   x1 rows 5..7 and row 0 blocked -> 7 (min_gap 1..3); 0 with min_gap 4 (the run of three
  //      is too short, and a run at the top counts whatever its length)
  //   x2 obstacle at row 4 only -> 4 (min_gap 1); -1 (min_gap >= 2: no long run, row 0 free)
  //   x3 hole at 6, floor 3..5, obstacle 0..2 -> 6 (min_gap 1); 2 (min_gap 2: rows 1..2 are a
  //      run of two; 3: rows 0..2; 4: rows 0..2, at the top)
  //   x4 row 0 only -> 0
  //   x5 rows 5..6 and 0..1 blocked -> 6 (min_gap 1, 2); 1 (min_gap 3, 4: rows 0..1, at the top)
  const char *rows[8] = {".#.###",   // y0
                         "...#.#",   // y1
                         "...#..",   // y2
                         "......",   // y3
                         "..#...",   // y4
                         ".#...#",   // y5
                         ".#.#.#",   // y6
                         ".#...."};  // y7
  const int w = 6, h = 8;
  std::vector<uint8_t> mask(size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) mask[size_t(y) * w + x] = rows[y][x] == '#' ? 0 : 200;
  EXPECT_EQ(free_space(mask, w, h, 1), (std::vector<int16_t>{-1, 7, 4, 6, 0, 6}));
  EXPECT_EQ(free_space(mask, w, h, 2), (std::vector<int16_t>{-1, 7, -1, 2, 0, 6}));
  EXPECT_EQ(free_space(mask, w, h, 3), (std::vector<int16_t>{-1, 7, -1, 2, 0, 1}));
  EXPECT_EQ(free_space(mask, w, h, 4), (std::vector<int16_t>{-1, 0, -1, 2, 0, 1}));
}

TEST(FreeSpace, MatchesTheSceneColumnTruth) {
  // The renderer's per-pixel surface map (what each pixel centre sees) as the floor mask: with
  // min_gap 1 the free space must be the scene's boundary_row, computed by its own geometry.
  const bvb::World world = bvb::load_arena("boxes");
  const bvb::Pose poses[] = {{24, 30, 0}, {60, 30, 60}, {30, 80, -30}, {70, 70, 135}};
  for (const auto &pose : poses) {
    const bvb::Camera cam = bvb::Camera::standard(160, 120);
    bvb::RenderOptions opt;
    opt.supersample = 1;
    const bvb::RenderResult r = bvb::render(world, pose, cam, opt);
    const bvb::ColumnTruth truth = bvb::column_truth(world, pose, cam);
    std::vector<uint8_t> mask(size_t(cam.width) * cam.height);
    for (size_t i = 0; i < mask.size(); ++i) mask[i] = r.surface[i] == bvb::kSurfaceFloor ? 255 : 0;
    const auto rows = free_space(mask, cam.width, cam.height, 1);
    int differ = 0;
    for (int x = 0; x < cam.width; ++x) differ += rows[size_t(x)] != truth.boundary_row[size_t(x)];
    // Both say which pixel centres see the floor (the truth by its own ray walk per column).
    EXPECT_EQ(differ, 0) << "pose " << pose.x_in << "," << pose.y_in << "," << pose.heading_deg;
  }
}

}  // namespace
