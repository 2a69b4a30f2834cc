// Colour blobs (bvb/blobs.h) on hand-made UYVY frames, and against an independent flood-fill
// labelling of the same definition.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <deque>
#include <vector>

#include "bvb/blobs.h"

namespace {

// A frame as planes: Y per pixel, U and V per pixel pair (as UYVY carries them).
struct Frame {
  int w, h;
  std::vector<uint8_t> Y, U, V;
  Frame(int w_, int h_, int y, int u, int v)
      : w(w_), h(h_), Y(size_t(w_) * h_, uint8_t(y)), U(size_t(w_ / 2) * h_, uint8_t(u)), V(size_t(w_ / 2) * h_, uint8_t(v)) {}
  // Paints x0..x1, y0..y1 inclusive; x0 even and x1 odd so that chroma pairs stay whole.
  void rect(int x0, int y0, int x1, int y1, int y, int u, int v) {
    for (int yy = y0; yy <= y1; ++yy)
      for (int x = x0; x <= x1; ++x) {
        Y[size_t(yy) * w + x] = uint8_t(y);
        U[size_t(yy) * (w / 2) + x / 2] = uint8_t(u);
        V[size_t(yy) * (w / 2) + x / 2] = uint8_t(v);
      }
  }
  std::vector<uint8_t> uyvy() const {
    std::vector<uint8_t> d(size_t(2) * w * h);
    for (int y = 0; y < h; ++y)
      for (int k = 0; k < w / 2; ++k) {
        uint8_t *q = &d[(size_t(y) * w + 2 * k) * 2];
        q[0] = U[size_t(y) * (w / 2) + k];
        q[1] = Y[size_t(y) * w + 2 * k];
        q[2] = V[size_t(y) * (w / 2) + k];
        q[3] = Y[size_t(y) * w + 2 * k + 1];
      }
    return d;
  }
};

struct Result {
  std::vector<bvb_blob> blobs;
  bvb_blob_summary sum;
  int32_t ret;
};

Result detect(const Frame &f, const bvb_blob_params &p, int label_cap = -1) {
  if (label_cap < 0) label_cap = f.w * f.h;
  Result r;
  r.blobs.assign(size_t(p.nclasses * p.max_blobs), bvb_blob{-7, -7, -7, -7, -7, -7, -7, -7});
  std::vector<uint32_t> scratch(size_t(BVB_BLOBS_SCRATCH_BYTES(f.w, label_cap)) / 4 + 1);
  const auto bytes = f.uyvy();
  r.ret = bvb_blobs_uyvy_c(bytes.data(), 2 * f.w, f.w, f.h, &p, r.blobs.data(), &r.sum, scratch.data(), label_cap);
  return r;
}

bvb_blob_params params(int nclasses, int conn, int max_blobs, int min_count) {
  bvb_blob_params p{};
  p.nclasses = nclasses, p.connectivity = conn, p.max_blobs = max_blobs, p.min_count = min_count;
  return p;
}

void expect_blob(const bvb_blob &b, int cls, int count, int x0, int y0, int x1, int y1, int sx, int sy) {
  EXPECT_EQ(b.cls, cls);
  EXPECT_EQ(b.count, count);
  EXPECT_EQ(b.min_x, x0);
  EXPECT_EQ(b.min_y, y0);
  EXPECT_EQ(b.max_x, x1);
  EXPECT_EQ(b.max_y, y1);
  EXPECT_EQ(b.sum_x, sx);
  EXPECT_EQ(b.sum_y, sy);
}

TEST(Blobs, TwoColouredRectanglesOfKnownSizeAndCentroid) {
  // Grey background; red (V high) rectangles 10x8 at (4..13, 5..12) and 4x3 at (30..33,
  // 25..27); a blue (U high) 16x12 rectangle at (20..35, 10..21).
  Frame f(40, 30, 128, 128, 128);
  f.rect(4, 5, 13, 12, 80, 100, 220);
  f.rect(30, 25, 33, 27, 80, 100, 220);
  f.rect(20, 10, 35, 21, 60, 220, 110);
  bvb_blob_params p = params(2, 8, 4, 1);
  p.cls[0] = {0, 255, 0, 255, 200, 255};  // red: V >= 200
  p.cls[1] = {0, 255, 200, 255, 0, 255};  // blue: U >= 200
  Result r = detect(f, p);
  // Red, largest first: 80 px, x sum (4 + .. + 13) * 8 rows = 680, y sum (5 + .. + 12) * 10 = 680
  // (centroid 8.5, 8.5); then 12 px, x sum (30 + .. + 33) * 3 = 378, y sum (25 + 26 + 27) * 4 = 312.
  expect_blob(r.blobs[0], 0, 80, 4, 5, 13, 12, 680, 680);
  expect_blob(r.blobs[1], 0, 12, 30, 25, 33, 27, 378, 312);
  expect_blob(r.blobs[2], 0, 0, 0, 0, 0, 0, 0, 0);  // unused slots are zero
  expect_blob(r.blobs[3], 0, 0, 0, 0, 0, 0, 0, 0);
  // Blue: 192 px, x sum (20 + .. + 35) * 12 = 5280, y sum (10 + .. + 21) * 16 = 2976
  // (centroid 27.5, 15.5).
  expect_blob(r.blobs[4], 1, 192, 20, 10, 35, 21, 5280, 2976);
  EXPECT_EQ(r.blobs[5].count, 0);
  EXPECT_EQ(r.sum.found[0], 2);
  EXPECT_EQ(r.sum.found[1], 1);
  for (int c = 2; c < 8; ++c) EXPECT_EQ(r.sum.found[c], 0);
  EXPECT_EQ(r.sum.dropped, 0);
  EXPECT_EQ(r.ret, 3);

  // One slot per class: the largest of each; found still counts both red blobs.
  p.max_blobs = 1;
  r = detect(f, p);
  expect_blob(r.blobs[0], 0, 80, 4, 5, 13, 12, 680, 680);
  expect_blob(r.blobs[1], 1, 192, 20, 10, 35, 21, 5280, 2976);
  EXPECT_EQ(r.sum.found[0], 2);
  // A minimum size of 13 drops the small red blob.
  p.max_blobs = 4, p.min_count = 13;
  r = detect(f, p);
  EXPECT_EQ(r.sum.found[0], 1);
  EXPECT_EQ(r.blobs[1].count, 0);
}

TEST(Blobs, DiagonalContactsConnectOnlyWithEightConnectivity) {
  // A staircase of five single bright pixels, classified by Y alone.
  Frame f(12, 8, 16, 128, 128);
  for (int i = 0; i < 5; ++i) f.Y[size_t(1 + i) * 12 + 3 + i] = 250;
  bvb_blob_params p = params(1, 8, 8, 1);
  p.cls[0] = {200, 255, 0, 255, 0, 255};
  Result r = detect(f, p);
  EXPECT_EQ(r.sum.found[0], 1);
  expect_blob(r.blobs[0], 0, 5, 3, 1, 7, 5, 3 + 4 + 5 + 6 + 7, 1 + 2 + 3 + 4 + 5);
  p.connectivity = 4;
  r = detect(f, p);
  EXPECT_EQ(r.sum.found[0], 5);
  // Equal sizes: in the raster order of their first pixels, top to bottom.
  for (int i = 0; i < 5; ++i) expect_blob(r.blobs[size_t(i)], 0, 1, 3 + i, 1 + i, 3 + i, 1 + i, 3 + i, 1 + i);
}

TEST(Blobs, EqualSizesAreOrderedByFirstPixel) {
  // Three 2x2 blobs of one class, painted in the order B (row 2, x 10), A (row 2, x 4),
  // C (row 1, x 14): the raster order of their first pixels is C (row 1), then A, B (row 2,
  // left to right). A 3x3 blob D further down is larger and comes first.
  Frame f(20, 10, 16, 128, 128);
  auto box = [&](int x0, int y0, int n) {
    for (int y = y0; y < y0 + n; ++y)
      for (int x = x0; x < x0 + n; ++x) f.Y[size_t(y) * 20 + x] = 240;
  };
  box(10, 2, 2);
  box(4, 2, 2);
  box(14, 1, 2);
  box(1, 6, 3);
  bvb_blob_params p = params(1, 8, 8, 1);
  p.cls[0] = {200, 255, 0, 255, 0, 255};
  const Result r = detect(f, p);
  ASSERT_EQ(r.sum.found[0], 4);
  EXPECT_EQ(r.blobs[0].count, 9);
  EXPECT_EQ(r.blobs[0].min_x, 1);
  EXPECT_EQ(r.blobs[1].min_x, 14);
  EXPECT_EQ(r.blobs[2].min_x, 4);
  EXPECT_EQ(r.blobs[3].min_x, 10);
}

TEST(Blobs, ShapesThatMergeLateAreOneBlob) {
  // A "W": three vertical bars joined at the bottom, and a spiral-like hook: labels made apart
  // on the first rows must merge into one blob with all statistics.
  Frame f(24, 12, 16, 128, 128);
  auto px = [&](int x, int y) { f.Y[size_t(y) * 24 + x] = 240; };
  for (int y = 1; y <= 8; ++y) px(2, y), px(6, y), px(10, y);
  for (int x = 2; x <= 10; ++x) px(x, 9);
  // Hook: top bar, right bar down, bottom bar back left, then up again short of the top.
  for (int x = 14; x <= 21; ++x) px(x, 1), px(x, 10);
  for (int y = 1; y <= 10; ++y) px(21, y);
  for (int y = 4; y <= 10; ++y) px(14, y);
  bvb_blob_params p = params(1, 4, 4, 1);
  p.cls[0] = {200, 255, 0, 255, 0, 255};
  const Result r = detect(f, p);
  ASSERT_EQ(r.sum.found[0], 2);
  // W: 3 bars of 8 + bottom row of 9 = 33 pixels. Hook: 8 + 8 + 8 (rows 2..9 of x 21) + 6
  // (rows 4..9 of x 14) = 30.
  int w_sx = 0, w_sy = 0;
  for (int y = 1; y <= 8; ++y) w_sx += 2 + 6 + 10, w_sy += 3 * y;
  for (int x = 2; x <= 10; ++x) w_sx += x, w_sy += 9;
  expect_blob(r.blobs[0], 0, 33, 2, 1, 10, 9, w_sx, w_sy);
  EXPECT_EQ(r.blobs[1].count, 30);
  EXPECT_EQ(r.blobs[1].min_x, 14);
  EXPECT_EQ(r.blobs[1].max_y, 10);
}

TEST(Blobs, OverlappingClassesGoToTheLowestNumber) {
  Frame f(8, 4, 100, 100, 100);
  bvb_blob_params p = params(3, 8, 2, 1);
  p.cls[0] = {0, 50, 0, 255, 0, 255};     // holds nothing here
  p.cls[1] = {90, 110, 90, 110, 90, 110};  // holds every pixel
  p.cls[2] = {0, 255, 0, 255, 0, 255};     // too, but comes later
  const Result r = detect(f, p);
  EXPECT_EQ(r.sum.found[0], 0);
  EXPECT_EQ(r.sum.found[1], 1);
  EXPECT_EQ(r.sum.found[2], 0);
  expect_blob(r.blobs[2], 1, 32, 0, 0, 7, 3, 4 * 28, 8 * 6);
}

TEST(Blobs, FullLabelTableLeavesRunsOut) {
  // Two separate blobs and a table of one label: the second blob's runs find no label above
  // them and none free, so all of its pixels are dropped.
  Frame f(16, 6, 16, 128, 128);
  f.rect(0, 0, 3, 1, 240, 128, 128);   // 8 px, first
  f.rect(8, 2, 13, 4, 240, 128, 128);  // 18 px
  bvb_blob_params p = params(1, 8, 2, 1);
  p.cls[0] = {200, 255, 0, 255, 0, 255};
  const Result r = detect(f, p, 1);
  EXPECT_EQ(r.sum.found[0], 1);
  EXPECT_EQ(r.sum.labels_used, 1);
  EXPECT_EQ(r.sum.dropped, 18);
  EXPECT_EQ(r.blobs[0].count, 8);
  const Result r0 = detect(f, p, 0);
  EXPECT_EQ(r0.sum.found[0], 0);
  EXPECT_EQ(r0.sum.dropped, 26);
}

// The definition again, independently: classify each pixel by testing the ranges directly,
// flood-fill each component from its first pixel in raster order, sort with std::stable_sort.
struct RefBlob {
  int cls, count, x0, y0, x1, y1, sx, sy, first;
};

void reference(const Frame &f, const bvb_blob_params &p, std::vector<bvb_blob> &out, int found[8]) {
  const int w = f.w, h = f.h;
  std::vector<int> cls(size_t(w) * h, -1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int Y = f.Y[size_t(y) * w + x], U = f.U[size_t(y) * (w / 2) + x / 2], V = f.V[size_t(y) * (w / 2) + x / 2];
      for (int c = 0; c < p.nclasses; ++c) {
        const bvb_blob_class &k = p.cls[c];
        if (Y >= k.y_min && Y <= k.y_max && U >= k.u_min && U <= k.u_max && V >= k.v_min && V <= k.v_max) {
          cls[size_t(y) * w + x] = c;
          break;
        }
      }
    }
  std::vector<char> seen(cls.size(), 0);
  std::vector<RefBlob> all;
  for (int i = 0; i < w * h; ++i) {
    if (cls[size_t(i)] < 0 || seen[size_t(i)]) continue;
    RefBlob b{cls[size_t(i)], 0, w, h, -1, -1, 0, 0, i};
    std::deque<int> q{i};
    seen[size_t(i)] = 1;
    while (!q.empty()) {
      const int k = q.front();
      q.pop_front();
      const int x = k % w, y = k / w;
      ++b.count, b.sx += x, b.sy += y;
      b.x0 = std::min(b.x0, x), b.x1 = std::max(b.x1, x), b.y0 = std::min(b.y0, y), b.y1 = std::max(b.y1, y);
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          if (!dx && !dy) continue;
          if (p.connectivity != 8 && dx && dy) continue;
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
          const int n = ny * w + nx;
          if (!seen[size_t(n)] && cls[size_t(n)] == b.cls) seen[size_t(n)] = 1, q.push_back(n);
        }
    }
    all.push_back(b);
  }
  std::stable_sort(all.begin(), all.end(), [](const RefBlob &a, const RefBlob &b) {
    return a.count != b.count ? a.count > b.count : a.first < b.first;
  });
  out.assign(size_t(p.nclasses * p.max_blobs), bvb_blob{0, 0, 0, 0, 0, 0, 0, 0});
  for (int c = 0; c < 8; ++c) found[c] = 0;
  for (const auto &b : all) {
    if (b.count < p.min_count) continue;
    const int n = found[b.cls]++;
    if (n < p.max_blobs) out[size_t(b.cls * p.max_blobs + n)] = {b.cls, b.count, b.x0, b.y0, b.x1, b.y1, b.sx, b.sy};
  }
}

TEST(Blobs, MatchesIndependentLabelling) {
  uint32_t s = 4242;
  auto rnd = [&]() { return s = s * 1664525u + 1013904223u, s >> 8; };
  for (int trial = 0; trial < 150; ++trial) {
    const int w = 2 * (1 + int(rnd() % 20)), h = 1 + int(rnd() % 25);
    Frame f(w, h, int(rnd() % 256), int(rnd() % 256), int(rnd() % 256));
    // Few levels per channel so that classes form blobs of every shape, plus rectangles.
    const int levels = 2 + int(rnd() % 3);
    for (auto &v : f.Y) v = uint8_t(rnd() % levels * (255 / (levels - 1)));
    if (trial % 2)
      for (auto &v : f.U) v = uint8_t(rnd() % levels * (255 / (levels - 1)));
    for (int b = int(rnd() % 5); b > 0; --b) {
      const int x0 = int(rnd() % (w / 2)) * 2, y0 = int(rnd() % h);
      f.rect(x0, y0, std::min(w - 1, x0 + 1 + 2 * int(rnd() % 6)), std::min(h - 1, y0 + int(rnd() % 8)),
             int(rnd() % 256), int(rnd() % 256), int(rnd() % 256));
    }
    bvb_blob_params p = params(1 + int(rnd() % 8), rnd() % 2 ? 8 : 4, 1 + int(rnd() % 6), 1 + int(rnd() % 3));
    for (int c = 0; c < p.nclasses; ++c) {
      int r[6];
      for (int k = 0; k < 3; ++k) {
        const int a = int(rnd() % 256), b = int(rnd() % 256);
        r[2 * k] = std::min(a, b), r[2 * k + 1] = rnd() % 3 ? std::max(a, b) : 255;
      }
      p.cls[c] = {r[0], r[1], r[2], r[3], r[4], r[5]};
    }
    const Result got = detect(f, p);
    std::vector<bvb_blob> want;
    int found[8];
    reference(f, p, want, found);
    ASSERT_EQ(got.blobs.size(), want.size());
    for (size_t i = 0; i < want.size(); ++i) {
      const bvb_blob &a = got.blobs[i], &b = want[i];
      ASSERT_TRUE(a.cls == b.cls && a.count == b.count && a.min_x == b.min_x && a.min_y == b.min_y &&
                  a.max_x == b.max_x && a.max_y == b.max_y && a.sum_x == b.sum_x && a.sum_y == b.sum_y)
          << "trial " << trial << " slot " << i << ": got class " << a.cls << " count " << a.count << " box (" << a.min_x
          << "," << a.min_y << ")-(" << a.max_x << "," << a.max_y << "), want class " << b.cls << " count " << b.count
          << " box (" << b.min_x << "," << b.min_y << ")-(" << b.max_x << "," << b.max_y << ")";
    }
    for (int c = 0; c < 8; ++c) EXPECT_EQ(got.sum.found[c], found[c]) << "trial " << trial << " class " << c;
    EXPECT_EQ(got.sum.dropped, 0);
  }
}

}  // namespace
