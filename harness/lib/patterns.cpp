#include "patterns.h"

#include <cstdlib>
#include <stdexcept>
#include <sys/stat.h>

#include "io.h"

namespace bvb {

const std::vector<Pattern> &all_patterns() {
  static const std::vector<Pattern> p = {Pattern::Zero,    Pattern::Max,   Pattern::Checker,
                                         Pattern::RampX,   Pattern::RampY, Pattern::Impulse,
                                         Pattern::Edges,   Pattern::Noise, Pattern::Runs,
                                         Pattern::Real};
  return p;
}

const char *pattern_name(Pattern p) {
  switch (p) {
    case Pattern::Zero: return "zero";
    case Pattern::Max: return "max";
    case Pattern::Checker: return "checker";
    case Pattern::RampX: return "ramp-x";
    case Pattern::RampY: return "ramp-y";
    case Pattern::Impulse: return "impulse";
    case Pattern::Edges: return "edges";
    case Pattern::Noise: return "noise";
    case Pattern::Runs: return "runs";
    case Pattern::Real: return "real";
  }
  return "?";
}

std::string default_frames_real() {
  const char *e = std::getenv("BFBENCH_FRAMES_REAL");
  return e && *e ? e : BVB_FRAMES_REAL;
}

namespace {
const char *const kGreyFrames[] = {"RubberWhale/frame10.pgm", "Hydrangea/frame10.pgm",
                                   "Dimetrodon/frame10.pgm",  "Grove2/frame10.pgm",
                                   "Urban2/frame10.pgm",      "Yosemite/yos9.pgm",
                                   "Rubic/rubic.0.pgm"};
}  // namespace

bool frames_real_present(const std::string &dir) {
  if (dir.empty()) return false;
  struct stat st;
  for (const char *f : kGreyFrames)
    if (stat((dir + "/" + f).c_str(), &st) != 0) return false;
  return true;
}

bool frames_required() {
  const char *e = std::getenv("BVB_REQUIRE_FRAMES");
  return e && std::string(e) == "1";
}

std::string frames_missing_message(const std::string &dir) {
  return "real frames not found at " + (dir.empty() ? std::string("(none given)") : dir) +
         (frames_required() ? " and BVB_REQUIRE_FRAMES=1" : ": real-frame cases skipped (BVB_REQUIRE_FRAMES=1 makes this an error)");
}

namespace {
// A lattice value of octave `o` at cell (cx, cy): splitmix of the three, one byte.
int lattice(int64_t cx, int64_t cy, int o, uint64_t seed) {
  Rng r(seed ^ (uint64_t(cx) * 0x9E3779B97F4A7C15ull) ^ (uint64_t(cy) * 0xC2B2AE3D27D4EB4Full) ^ (uint64_t(o) << 56));
  return int(r.next() >> 56);
}
int64_t floor_div(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
}  // namespace

uint8_t hermetic_texture_at(int64_t xq, int64_t yq, uint64_t seed) {
  // Octaves with cells of 32, 16, 8 and 4 pixels weighted 8:4:2:2 (of 16), bilinear within a
  // cell in 1/256 of the cell: smooth enough to track, with corners and texture at every scale.
  static const int kCellLog2[] = {5, 4, 3, 2}, kWeight[] = {8, 4, 2, 2};
  int64_t sum = 0;
  for (int o = 0; o < 4; ++o) {
    const int64_t cell = int64_t(256) << kCellLog2[o];  // in 1/256 pixel
    const int64_t cx = floor_div(xq, cell), cy = floor_div(yq, cell);
    const int64_t fx = ((xq - cx * cell) << 8) / cell, fy = ((yq - cy * cell) << 8) / cell;  // 0..255
    const int64_t a = lattice(cx, cy, o, seed), b = lattice(cx + 1, cy, o, seed);
    const int64_t c = lattice(cx, cy + 1, o, seed), d = lattice(cx + 1, cy + 1, o, seed);
    const int64_t top = a * (256 - fx) + b * fx, bottom = c * (256 - fx) + d * fx;  // x 256
    sum += kWeight[o] * (top * (256 - fy) + bottom * fy);                            // x 65536
  }
  // The octaves' sum is a mean near 128 with a narrow spread: stretch it to use the 8 bits.
  int64_t v = (sum + (int64_t(1) << 19)) >> 20;  // 0..255, mean 127.5
  v = 128 + (v - 128) * 5 / 2;
  return uint8_t(v < 0 ? 0 : v > 255 ? 255 : v);
}

Image hermetic_texture(int w, int h, uint64_t seed, int32_t dx_q8, int32_t dy_q8) {
  Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      img.at(x, y) = hermetic_texture_at(int64_t(x) * 256 - dx_q8, int64_t(y) * 256 - dy_q8, seed);
  return img;
}

Image real_crop(const std::string &dir, int w, int h, Rng &caller) {
  // One draw from the caller's stream, found or not: what the caller draws next is the same.
  Rng rng(caller.next());
  const std::string path = dir + "/" + kGreyFrames[rng.uniform(0, 6)];
  struct stat st;
  if (dir.empty() || stat(path.c_str(), &st) != 0) return {};
  static std::string cached_path;
  static Image cached;
  if (cached_path != path) {
    cached = read_pnm(path);
    cached_path = path;
  }
  const Image &src = cached;
  Image out(w, h);
  // Tile when the crop is larger than the frame (only for sizes above 640x480).
  const int x0 = src.width > w ? rng.uniform(0, src.width - w) : 0;
  const int y0 = src.height > h ? rng.uniform(0, src.height - h) : 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) out.at(x, y) = src.at((x0 + x) % src.width, (y0 + y) % src.height);
  return out;
}

std::vector<uint8_t> make_plane(Pattern p, int w, int h, int stride, Rng &rng,
                                const std::string &frames_real) {
  std::vector<uint8_t> d(size_t(stride) * (h - 1) + w);
  for (auto &v : d) v = uint8_t(rng.u32());  // padding and, for Noise, everything
  Image real;
  if (p == Pattern::Real) {
    real = real_crop(frames_real, w, h, rng);
    if (real.data.empty())
      throw std::logic_error("a real-frame case was generated without the frames (" + frames_real +
                             "): generate it only when Checker::have_frames()");
  }
  const int ix = rng.uniform(0, w - 1), iy = rng.uniform(0, h - 1);
  const int ex = rng.uniform(0, w), ey = rng.uniform(0, h);
  int run_left = 0, run_kind = 0;
  uint8_t run_value = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      uint8_t &v = d[size_t(y) * stride + x];
      switch (p) {
        case Pattern::Zero: v = 0; break;
        case Pattern::Max: v = 255; break;
        case Pattern::Checker: v = ((x ^ y) & 1) ? 255 : 0; break;
        case Pattern::RampX: v = uint8_t(w > 1 ? x * 255 / (w - 1) : 128); break;
        case Pattern::RampY: v = uint8_t(h > 1 ? y * 255 / (h - 1) : 128); break;
        case Pattern::Impulse: v = (x == ix && y == iy) ? 255 : 0; break;
        // A saturating step edge at a random place, horizontal and vertical.
        case Pattern::Edges: v = (x >= ex) != (y >= ey) ? 255 : 0; break;
        case Pattern::Noise: break;
        case Pattern::Runs:
          // Random-length runs of 0, 255, random and alternating values, as checkasm does.
          if (run_left == 0) {
            run_left = rng.uniform(1, 24);
            run_kind = rng.uniform(0, 3);
            run_value = uint8_t(rng.u32());
          }
          --run_left;
          v = run_kind == 0 ? 0 : run_kind == 1 ? 255 : run_kind == 2 ? uint8_t(rng.u32())
                                                                      : ((x + y) & 1 ? run_value : uint8_t(~run_value));
          break;
        case Pattern::Real: v = real.at(x, y); break;
      }
    }
  }
  return d;
}

std::vector<Size> check_sizes(int min_w, int min_h, Rng &rng, bool campaign) {
  std::vector<Size> s = {{min_w, min_h}, {min_w + 1, min_h}, {min_w, min_h + 1},
                         {std::max(min_w, 7), std::max(min_h, 5)},
                         {std::max(min_w, 16), std::max(min_h, 9)},
                         {std::max(min_w, 33), std::max(min_h, 17)},
                         {160, 120}};
  const int nrandom = campaign ? 12 : 3;
  for (int i = 0; i < nrandom; ++i)
    s.push_back({rng.uniform(min_w, campaign ? 400 : 96), rng.uniform(min_h, campaign ? 300 : 64)});
  if (campaign) {
    s.push_back({320, 240});
    s.push_back({640, 480});
    s.push_back({639, 479});
  }
  return s;
}

int pick_stride(int w, Rng &rng, int multiple) {
  int s = w;
  if (rng.uniform(0, 2) == 0) s += rng.uniform(1, 9);
  return (s + multiple - 1) / multiple * multiple;
}

}  // namespace bvb
