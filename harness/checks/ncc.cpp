// Check, bench and run for bvb/ncc.h: the NCC matcher (ncc_match) and its dense score map
// (ncc_scoremap).
//
// Bench: 32 feature points on a grid over the frame, r = 5 (11x11 template), s = 8 (289
// candidates each), frame 2 = frame 1 (uniform noise) moved by (3, -2) plus noise. CheckCall::
// pixels holds the number of candidate positions (32 * 289 = 9248), so the bench table's "c/px"
// columns read as cycles per candidate position, and the bound column is the MAC bound: 121
// multiply-accumulates per candidate, two per cycle, 60.5 cycles.
#include "bvb/ncc.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include "family.h"
#include "io.h"
#include "patterns.h"
#include "formats.h"
#include "names.h"

namespace bvb {
namespace {

struct Frames {
  int w = 0, h = 0, stride = 0;
  std::vector<uint8_t> f1, f2;
};

std::vector<uint8_t> pack_points(const std::vector<std::pair<int, int>> &pts) {
  std::vector<uint8_t> b(pts.size() * 4);
  for (size_t i = 0; i < pts.size(); ++i) {
    const int16_t x = int16_t(pts[i].first), y = int16_t(pts[i].second);
    std::memcpy(&b[4 * i], &x, 2);
    std::memcpy(&b[4 * i + 2], &y, 2);
  }
  return b;
}

size_t scratch_bytes(int r, int s) {
  if (r < 1 || r > BVB_NCC_MAX_RADIUS || s < 1 || s > BVB_NCC_MAX_SEARCH) return 64;
  return BVB_NCC_SCRATCH_SIZE(r, s);
}

CheckCall match_call(const Frames &fr, const std::vector<std::pair<int, int>> &pts, int r, int s,
                     const std::string &case_name) {
  CheckCall c;
  c.kernel = "ncc_match";
  c.case_name = case_name;
  int valid = 0;
  for (auto p : pts)
    valid += p.first - r - s >= 0 && p.first + r + s < fr.w && p.second - r - s >= 0 && p.second + r + s < fr.h;
  c.pixels = double(valid) * (2 * s + 1) * (2 * s + 1);
  const View fv{1, false, fr.w, fr.h, fr.stride};
  const int n = int(pts.size());
  int i1 = c.in("frame1", fr.f1, fv);
  int i2 = c.in("frame2", fr.f2, fv);
  int ip = c.in("points", pack_points(pts), View{2, true, 2, std::max(n, 1), 2});
  int ir = c.out("results", size_t(std::max(n, 1)) * 8, View{2, true, 4, std::max(n, 1), 4});
  int is = c.scratch("scratch", scratch_bytes(r, s));
  const int stride = fr.stride, w = fr.w, h = fr.h;
  c.buf(i1).buf(i2).word(stride).word(w).word(h).buf(ip).word(n).word(r).word(s).buf(ir).buf(is);
  c.host = [=](HostBuffers &m) {
    bvb_ncc_match_c(m.u8(i1), m.u8(i2), stride, w, h, m.s16(ip), n, r, s, m.s16(ir), m.u8(is));
  };
  return c;
}

CheckCall scoremap_call(const Frames &fr, int x, int y, int r, int s, const std::string &case_name) {
  CheckCall c;
  c.kernel = "ncc_scoremap";
  c.case_name = case_name;
  const int side = 2 * std::max(s, 0) + 1;
  c.pixels = double(side) * side;
  const View fv{1, false, fr.w, fr.h, fr.stride};
  int i1 = c.in("frame1", fr.f1, fv);
  int i2 = c.in("frame2", fr.f2, fv);
  int im = c.out("map", size_t(side * side + 1) * 2, View{2, true, side, side + 1, side});
  int is = c.scratch("scratch", scratch_bytes(r, s));
  const int stride = fr.stride, w = fr.w, h = fr.h;
  c.buf(i1).buf(i2).word(stride).word(w).word(h).word(x).word(y).word(r).word(s).buf(im).buf(is);
  c.host = [=](HostBuffers &m) {
    bvb_ncc_scoremap_c(m.u8(i1), m.u8(i2), stride, w, h, x, y, r, s, m.s16(im), m.u8(is));
  };
  return c;
}

// Frame 2 as frame 1 seen after the scene moved by (tx, ty) (edges clamped), plus noise of
// amplitude up to `noise`; the row padding stays as it was.
std::vector<uint8_t> moved(const Frames &fr, int tx, int ty, int noise, Rng &rng) {
  std::vector<uint8_t> out = fr.f1;
  for (int y = 0; y < fr.h; ++y)
    for (int x = 0; x < fr.w; ++x) {
      const int sx = std::min(std::max(x - tx, 0), fr.w - 1), sy = std::min(std::max(y - ty, 0), fr.h - 1);
      int v = fr.f1[size_t(sy) * fr.stride + sx];
      if (noise) v += rng.uniform(-noise, noise);
      out[size_t(y) * fr.stride + x] = uint8_t(std::min(255, std::max(0, v)));
    }
  return out;
}

// A tile repeating every px columns and py rows: exact copies of every template, hence ties.
std::vector<uint8_t> tiled(int w, int h, int stride, int px, int py, Rng &rng) {
  std::vector<uint8_t> tile(size_t(px) * py), out(size_t(stride) * (h - 1) + w);
  for (auto &v : tile) v = uint8_t(rng.u32());
  for (auto &v : out) v = uint8_t(rng.u32());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) out[size_t(y) * stride + x] = tile[size_t(y % py) * px + x % px];
  return out;
}

// Points of every kind for a w x h frame: random legal ones, ones on the four limits of the legal
// area and one past them, far outside, duplicates.
std::vector<std::pair<int, int>> pick_points(int w, int h, int r, int s, int count, Rng &rng) {
  std::vector<std::pair<int, int>> pts;
  const int lo = r + s, hix = w - 1 - r - s, hiy = h - 1 - r - s;
  const bool legal = hix >= lo && hiy >= lo;
  for (int i = 0; i < count; ++i) {
    const int kind = rng.uniform(0, 9);
    if (legal && kind <= 4) {
      pts.push_back({rng.uniform(lo, hix), rng.uniform(lo, hiy)});
    } else if (legal && kind <= 6) {
      const int x = rng.uniform(0, 1) ? lo : hix, y = rng.uniform(0, 1) ? lo : hiy;
      pts.push_back({x, y});
    } else if (kind == 7) {
      const int x = rng.uniform(0, 1) ? lo - 1 : hix + 1;
      pts.push_back({x, rng.uniform(std::min(lo, hiy), std::max(lo, hiy))});
    } else if (kind == 8) {
      pts.push_back({rng.uniform(-40, w + 40), rng.uniform(0, 1) ? lo - 1 - rng.uniform(0, 3) : hiy + 1});
    } else if (!pts.empty()) {
      pts.push_back(pts[rng.uniform(0, int(pts.size()) - 1)]);
    } else {
      pts.push_back({rng.uniform(-5, w + 5), rng.uniform(-5, h + 5)});
    }
  }
  return pts;
}

// An offset on the edge of the (2s+1)^2 search window: the last row (dy = s) or column (dx = s)
// most often, since those are the ones a sweep that stops a step early never visits; the first
// ones and the corners too.
std::pair<int, int> edge_offset(int s, Rng &rng) {
  const int k = rng.uniform(-s, s), kind = rng.uniform(0, 7);
  switch (kind) {
    case 0: case 1: return {k, s};
    case 2: case 3: return {s, k};
    case 4: return {s, s};
    case 5: return {-s, k};
    case 6: return {k, -s};
    default: return {rng.uniform(0, 1) ? -s : s, rng.uniform(0, 1) ? -s : s};
  }
}

// A second offset with the same |dx| + |dy| (a reflection or the transpose), so an exact copy
// there ties with the first and bvb/ncc.h's order (smaller dy, then smaller dx) picks the winner.
std::pair<int, int> tied_offset(std::pair<int, int> o, Rng &rng) {
  switch (rng.uniform(0, 3)) {
    case 0: return {-o.first, o.second};
    case 1: return {o.first, -o.second};
    case 2: return {-o.first, -o.second};
    default: return {o.second, o.first};
  }
}

// Copies frame 1's w x w template around (x, y) into frame 2 centred at (x + dx, y + dy).
void plant(Frames &fr, int x, int y, int r, std::pair<int, int> o) {
  for (int j = -r; j <= r; ++j)
    for (int i = -r; i <= r; ++i)
      fr.f2[size_t(y + o.second + j) * fr.stride + (x + o.first + i)] = fr.f1[size_t(y + j) * fr.stride + (x + i)];
}

// Frames at any byte offset, the int16 arrays on halfwords; then L1 or SDRAM.
void place(Checker &ck, CheckCall &c, Rng &rng) {
  for (auto &b : c.bufs) {
    if (b.name == "frame1" || b.name == "frame2") b.skew = uint32_t(rng.uniform(0, 3));
    else if (b.name != "scratch") b.skew = uint32_t(2 * rng.uniform(0, 1));
  }
  ck.place_randomly(c);
}

// A radius and search range that fit a w x h frame (when any does), favouring the robot's
// r = 5; sometimes ones that do not fit, so every point is on the border.
void pick_rs(int w, int h, Rng &rng, int &r, int &s) {
  const int m = (std::min(w, h) - 1) / 2;  // r + s must not exceed this for a legal point
  r = rng.uniform(0, 2) ? 5 : rng.uniform(1, BVB_NCC_MAX_RADIUS);
  s = rng.uniform(1, 8) == 1 ? rng.uniform(9, BVB_NCC_MAX_SEARCH) : rng.uniform(1, 8);
  if (m >= 2 && rng.uniform(0, 4)) {
    r = std::min(r, m - 1);
    s = std::min(s, m - r);
  }
}

std::string rs_name(int r, int s) { return "r" + std::to_string(r) + " s" + std::to_string(s); }

void check(Checker &ck) {
  Rng &rng = ck.rng();
  const std::string &real = ck.options().frames_real;
  const bool campaign = ck.options().campaign;
  {
    for (Size sz : check_sizes(1, 1, rng, campaign)) {
      // Few patterns on large frames: the C reference costs about a thousand cycles per candidate.
      const bool big = sz.w * sz.h > 40000;
      for (Pattern p : ck.patterns()) {
        if (big && rng.uniform(0, 3)) continue;
        int r, s;
        pick_rs(sz.w, sz.h, rng, r, s);
        if (big) s = std::min(s, 8);
        Frames fr;
        fr.w = sz.w;
        fr.h = sz.h;
        fr.stride = pick_stride(sz.w, rng);
        fr.f1 = make_plane(p, sz.w, sz.h, fr.stride, rng, real);
        // Frame 2: frame 1 moved (matches to find), or unrelated, or the same frame.
        const int kind = rng.uniform(0, 5);
        std::string how;
        if (kind <= 3) {
          const int tx = rng.uniform(-s - 1, s + 1), ty = rng.uniform(-s - 1, s + 1), noise = rng.uniform(0, 3) * 4;
          fr.f2 = moved(fr, tx, ty, noise, rng);
          how = "moved " + std::to_string(tx) + "," + std::to_string(ty) + " noise " + std::to_string(noise);
        } else if (kind == 4) {
          const Pattern q = ck.patterns()[rng.uniform(0, int(ck.patterns().size()) - 1)];
          fr.f2 = make_plane(q, sz.w, sz.h, fr.stride, rng, real);
          how = std::string("vs ") + pattern_name(q);
        } else {
          fr.f2 = fr.f1;
          how = "same";
        }
        const int npts = rng.uniform(0, big ? 3 : 6);
        auto pts = pick_points(sz.w, sz.h, r, s, npts, rng);
        char name[160];
        std::snprintf(name, sizeof name, "%dx%d stride %d %s %s %s, %d points", sz.w, sz.h, fr.stride,
                      rs_name(r, s).c_str(), pattern_name(p), how.c_str(), npts);
        CheckCall c = match_call(fr, pts, r, s, name);
        place(ck, c, rng);
        ck.add(std::move(c));
      }
    }
    // Ties: periodic scenes, moved by a few pixels, every template repeated across the search area.
    for (int i = 0; i < (campaign ? 12 : 4); ++i) {
      Frames fr;
      fr.w = rng.uniform(30, 90);
      fr.h = rng.uniform(30, 70);
      fr.stride = pick_stride(fr.w, rng);
      const int px = rng.uniform(1, 7), py = rng.uniform(1, 7);
      fr.f1 = tiled(fr.w, fr.h, fr.stride, px, py, rng);
      const int r = rng.uniform(1, BVB_NCC_MAX_RADIUS), s = rng.uniform(2, 7);
      const int tx = rng.uniform(-3, 3), ty = rng.uniform(-3, 3);
      fr.f2 = moved(fr, tx, ty, 0, rng);
      auto pts = pick_points(fr.w, fr.h, r, s, 5, rng);
      char name[160];
      std::snprintf(name, sizeof name, "%dx%d tile %dx%d moved %d,%d %s", fr.w, fr.h, px, py, tx, ty,
                    rs_name(r, s).c_str());
      CheckCall c = match_call(fr, pts, r, s, name);
      place(ck, c, rng);
      ck.add(std::move(c));
    }
    // Planted winners: frame 2 is unrelated noise but for an exact copy of each point's template
    // at an offset on its search window's edge (the last row or column most often), and in one
    // point in three a second copy tying with it. The points' search areas do not overlap, so
    // each copy is the unique best (score 1.0) or the tie's winner: a candidate sweep that
    // skips or shifts a row, a column or a pair of candidates gets the offset wrong. Half the
    // calls in the robot's layout (frames in SDRAM, scratch in L1: the memory DMA path of r = 5,
    // 5 <= s <= 8), half placed at random.
    for (int i = 0; i < (campaign ? 24 : 8); ++i) {
      const int r = rng.uniform(0, 2) ? 5 : rng.uniform(1, BVB_NCC_MAX_RADIUS);
      const int s = rng.uniform(0, 5) ? rng.uniform(5, 8) : rng.uniform(1, 10);
      const int side = 2 * (r + s) + 1, cols = rng.uniform(1, 4), rows = rng.uniform(1, 3);
      Frames fr;
      fr.w = cols * side + rng.uniform(0, 5);
      fr.h = rows * side + rng.uniform(0, 5);
      fr.stride = pick_stride(fr.w, rng);
      fr.f1 = make_plane(Pattern::Noise, fr.w, fr.h, fr.stride, rng, real);
      fr.f2 = make_plane(Pattern::Noise, fr.w, fr.h, fr.stride, rng, real);
      std::vector<std::pair<int, int>> pts;
      int ties = 0;
      for (int j = 0; j < rows; ++j)
        for (int k = 0; k < cols; ++k) {
          const int x = r + s + k * side, y = r + s + j * side;
          const auto o = edge_offset(s, rng);
          plant(fr, x, y, r, o);
          if (rng.uniform(0, 2) == 0) {
            const auto t = tied_offset(o, rng);
            // only where the two copies do not overlap (else the first is no longer exact)
            if (std::max(std::abs(t.first - o.first), std::abs(t.second - o.second)) > 2 * r) {
              plant(fr, x, y, r, t);
              ++ties;
            }
          }
          pts.push_back({x, y});
        }
      char name[160];
      std::snprintf(name, sizeof name, "%dx%d stride %d %s planted edge winners, %zu points, %d ties", fr.w,
                    fr.h, fr.stride, rs_name(r, s).c_str(), pts.size(), ties);
      CheckCall c = match_call(fr, pts, r, s, name);
      if (i % 2 == 0) {
        for (auto &b : c.bufs) {
          b.place = b.name == "scratch" ? BVB_PLACE_L1A : BVB_PLACE_SDRAM;
          if (b.name == "frame1" || b.name == "frame2") b.skew = uint32_t(rng.uniform(0, 3));
        }
        c.case_name += " frames SDRAM";
      } else {
        place(ck, c, rng);
      }
      ck.add(std::move(c));
    }
    // Many points in one call, legal ones mixed with border ones and repeats: the assembly copies
    // the next legal point's search area during the current one's MACs (r = 5, 5 <= s <= 10).
    for (int s : {5, 8, 10}) {
      Frames fr;
      fr.w = rng.uniform(70, 160);
      fr.h = rng.uniform(50, 120);
      fr.stride = pick_stride(fr.w, rng);
      const Pattern p = rng.uniform(0, 1) ? Pattern::Real : Pattern::Noise;
      if (p == Pattern::Real && !ck.have_frames()) {
        ck.skip_real();
        continue;
      }
      fr.f1 = make_plane(p, fr.w, fr.h, fr.stride, rng, real);
      fr.f2 = moved(fr, rng.uniform(-3, 3), rng.uniform(-3, 3), 4, rng);
      auto pts = pick_points(fr.w, fr.h, 5, s, s == 10 ? 10 : 16, rng);
      char name[160];
      std::snprintf(name, sizeof name, "%dx%d %s %s, %zu points", fr.w, fr.h, rs_name(5, s).c_str(),
                    pattern_name(p), pts.size());
      CheckCall c = match_call(fr, pts, 5, s, name);
      place(ck, c, rng);
      ck.add(std::move(c));
    }
    // Parameters out of range, and no points at all.
    for (auto rs : {std::pair{0, 4}, {BVB_NCC_MAX_RADIUS + 1, 4}, {3, 0}, {3, BVB_NCC_MAX_SEARCH + 1}, {-1, -1}, {3, 4}}) {
      Frames fr;
      fr.w = 40;
      fr.h = 30;
      fr.stride = 40;
      fr.f1 = make_plane(Pattern::Noise, 40, 30, 40, rng, real);
      fr.f2 = fr.f1;
      const bool none = rs.first == 3 && rs.second == 4;
      auto pts = none ? std::vector<std::pair<int, int>>{} : pick_points(40, 30, 3, 4, 3, rng);
      CheckCall c = match_call(fr, pts, rs.first, rs.second,
                               none ? std::string("no points") : "bad params " + rs_name(rs.first, rs.second));
      ck.add(std::move(c));
    }
  }
  {
    for (Size sz : check_sizes(1, 1, rng, campaign)) {
      for (int i = 0; i < 3; ++i) {
        const Pattern p = ck.patterns()[rng.uniform(0, int(ck.patterns().size()) - 1)];
        int r, s;
        pick_rs(sz.w, sz.h, rng, r, s);
        Frames fr;
        fr.w = sz.w;
        fr.h = sz.h;
        fr.stride = pick_stride(sz.w, rng);
        fr.f1 = make_plane(p, sz.w, sz.h, fr.stride, rng, real);
        const int tx = rng.uniform(-s, s), ty = rng.uniform(-s, s);
        fr.f2 = rng.uniform(0, 3) ? moved(fr, tx, ty, rng.uniform(0, 2) * 6, rng)
                                  : make_plane(Pattern::Noise, sz.w, sz.h, fr.stride, rng, real);
        const auto pt = pick_points(sz.w, sz.h, r, s, 1, rng)[0];
        char name[160];
        std::snprintf(name, sizeof name, "%dx%d stride %d %s %s at %d,%d", sz.w, sz.h, fr.stride,
                      rs_name(r, s).c_str(), pattern_name(p), pt.first, pt.second);
        CheckCall c = scoremap_call(fr, pt.first, pt.second, r, s, name);
        place(ck, c, rng);
        ck.add(std::move(c));
      }
    }
    Frames fr;
    fr.w = fr.h = fr.stride = 40;
    fr.f1 = fr.f2 = make_plane(Pattern::Noise, 40, 40, 40, rng, real);
    ck.add(scoremap_call(fr, 20, 20, 0, 3, "bad params r0 s3"));
    ck.add(scoremap_call(fr, 20, 20, 2, BVB_NCC_MAX_SEARCH + 1, "bad params r2 s17"));
  }
}

// The bench scene: uniform noise, and the same moved by (3, -2) with noise of +-8.
Frames bench_frames(int w, int h, Rng &rng) {
  Frames fr;
  fr.w = w;
  fr.h = h;
  fr.stride = w;
  fr.f1 = make_plane(Pattern::Noise, w, h, w, rng, "");
  fr.f2 = moved(fr, 3, -2, 8, rng);
  return fr;
}

constexpr int kBenchR = 5, kBenchS = 8, kBenchCols = 8, kBenchRows = 4;

std::vector<std::pair<int, int>> bench_points(int w, int h) {
  std::vector<std::pair<int, int>> pts;
  const int lo = kBenchR + kBenchS, hx = w - 1 - lo, hy = h - 1 - lo;
  for (int j = 0; j < kBenchRows; ++j)
    for (int i = 0; i < kBenchCols; ++i)
      pts.push_back({lo + (hx - lo) * i / (kBenchCols - 1), lo + (hy - lo) * j / (kBenchRows - 1)});
  return pts;
}

CheckCall bench_call(const std::string &kernel, int w, int h, Rng &rng) {
  const std::string name = size_name(w, h);
  Frames fr = bench_frames(w, h, rng);
  CheckCall c = kernel == "ncc_match" ? match_call(fr, bench_points(w, h), kBenchR, kBenchS, name)
                                      : scoremap_call(fr, w / 2, h / 2, kBenchR, kBenchS, name);
  // The robot's layout: frames in SDRAM, working buffers in L1.
  for (auto &b : c.bufs) b.place = b.name == "scratch" ? BVB_PLACE_L1A : BVB_PLACE_SDRAM;
  return c;
}

// 121 multiply-accumulates per candidate and two MAC units: 60.5 cycles per candidate.
double lower_bound(const std::string &kernel, int w, int h) {
  const double cand = (2 * kBenchS + 1) * (2 * kBenchS + 1);
  const double per = (2 * kBenchR + 1) * (2 * kBenchR + 1) / 2.0;
  return kernel == "ncc_match" ? per * cand * double(bench_points(w, h).size()) : per * cand;
}

RunPlan plan_run(RunRequest &req) {
  if (req.inputs.size() != 2) throw InputError(req.kernel + " takes two --in frames (frame 1, frame 2)");
  Image a = read_input(req, 0);
  Image b = read_input(req, 1);
  if (a.width != b.width || a.height != b.height) throw InputError(req.kernel + ": the two frames differ in size");
  const int r = req.params.get_int("r", 5, 1, BVB_NCC_MAX_RADIUS);
  const int s = req.params.get_int("s", 8, 1, BVB_NCC_MAX_SEARCH);
  Frames fr;
  fr.w = a.width;
  fr.h = a.height;
  fr.stride = a.width;
  fr.f1 = a.data;
  fr.f2 = b.data;
  RunPlan p;
  double npoints = 1;
  if (req.kernel == "ncc_match") {
    // Points on a cols x rows grid over the legal area (every point is matched).
    const int cols = req.params.get_int("cols", 8, 1, 64), rows = req.params.get_int("rows", 6, 1, 64);
    req.params.check_all_used();
    const int lo = r + s, hx = fr.w - 1 - lo, hy = fr.h - 1 - lo;
    if (hx < lo || hy < lo) throw InputError("ncc_match: the frame is smaller than one search area");
    std::vector<std::pair<int, int>> pts;
    for (int j = 0; j < rows; ++j)
      for (int i = 0; i < cols; ++i)
        pts.push_back({lo + (cols > 1 ? (hx - lo) * i / (cols - 1) : (hx - lo) / 2),
                       lo + (rows > 1 ? (hy - lo) * j / (rows - 1) : (hy - lo) / 2)});
    p.call = match_call(fr, pts, r, s, "run");
    npoints = double(pts.size());
    p.write = [pts](std::vector<std::vector<uint8_t>> &bufs, const std::string &path) {
      std::string text = "# x y dx dy score_q15 status\n";
      for (size_t i = 0; i < pts.size(); ++i) {
        int16_t v[4];
        std::memcpy(v, &bufs[3][8 * i], 8);
        char line[96];
        std::snprintf(line, sizeof line, "%d %d %d %d %d %d\n", pts[i].first, pts[i].second, v[0], v[1], v[2], v[3]);
        text += line;
      }
      write_text_output(path, text);
    };
    p.kind = OutputKind::Text;
    p.summary = size_name(fr.w, fr.h) + ", " + std::to_string(pts.size()) +
                " points, r " + std::to_string(r) + ", s " + std::to_string(s);
  } else {
    const int x = req.params.get_int("x", fr.w / 2, 0, fr.w - 1), y = req.params.get_int("y", fr.h / 2, 0, fr.h - 1);
    req.params.check_all_used();
    p.call = scoremap_call(fr, x, y, r, s, "run");
    const int side = 2 * s + 1;
    // The map as a grey image: score -1 .. 1 -> 0 .. 255.
    p.write = [side](std::vector<std::vector<uint8_t>> &bufs, const std::string &path) {
      Image out(side, side);
      for (int i = 0; i < side * side; ++i) {
        int16_t q;
        std::memcpy(&q, &bufs[2][2 * i], 2);
        out.data[i] = uint8_t((int(q) + 32768) >> 8);
      }
      write_image(path, out);
    };
    p.summary = size_name(fr.w, fr.h) + ", point " + std::to_string(x) + "," +
                std::to_string(y) + ", r " + std::to_string(r) + ", s " + std::to_string(s);
  }
  for (auto &bf : p.call.bufs) bf.place = bf.name == "scratch" ? BVB_PLACE_L1A : BVB_PLACE_WINDOW;
  // The default cycle limit fits the bench's 32 points; a run's grid of up to 64x64 points, or
  // a wider search, takes longer and would be reported as a hang. The C reference takes about 13
  // simulator cycles a template pixel per candidate (32 for the score map), the timing model
  // more: the limit allows 64, and at most what the watchdog counts.
  const double taps = double(2 * r + 1) * (2 * r + 1), cand = double(2 * s + 1) * (2 * s + 1);
  const double limit = npoints * cand * taps * 64;
  p.call.cycle_limit = uint32_t(std::clamp(limit, double(Target::kDefaultCycleLimit), 4.0e9));
  return p;
}

const Family kNcc{"ncc", {"ncc_match", "ncc_scoremap"}, check, bench_call, lower_bound, plan_run};
BVB_FAMILY(kNcc);

}  // namespace
}  // namespace bvb
