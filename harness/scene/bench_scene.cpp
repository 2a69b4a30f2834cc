#include "scene/bench_scene.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <mutex>
#include <set>
#include <sstream>

#include "io.h"
#include "sha256.h"
#include "names.h"

namespace bvb {

std::string bench_scene_dir(int w, int h) {
  if (!((w == 160 && h == 120) || (w == 320 && h == 240))) return "";
  return std::string(BVB_SOURCE_DIR) + "/frames/scenes/bench_boxes_" + size_name(w, h);
}

void verify_sha256sums(const std::string &dir, const std::vector<std::string> &required) {
  const std::string sums_path = dir + "/SHA256SUMS";
  const std::vector<uint8_t> sums = read_file(sums_path, 1 << 16);
  std::istringstream in(std::string(sums.begin(), sums.end()));
  std::string line;
  std::set<std::string> listed;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (line.empty()) continue;
    // "<digest>  <name>" (text mode) or "<digest> *<name>" (binary mode): the same bytes here.
    if (line.size() < 67 || line[64] != ' ' || (line[65] != ' ' && line[65] != '*') ||
        line.find_first_not_of("0123456789abcdef") < 64)
      throw InputError(sums_path + ":" + std::to_string(n) + ": not '<sha256 hex>  <file>'");
    const std::string want = line.substr(0, 64), name = line.substr(66);
    if (name.find('/') != std::string::npos)
      throw InputError(sums_path + ":" + std::to_string(n) + ": '" + name + "' is not a file in " + dir);
    const std::vector<uint8_t> bytes = read_file(dir + "/" + name);
    const std::string got = sha256_hex(bytes.data(), bytes.size());
    if (got != want)
      throw InputError(dir + "/" + name + ": SHA-256 " + got.substr(0, 16) + "... is not the " + want.substr(0, 16) +
                       "... of SHA256SUMS (the bench budgets were measured on those bytes)");
    listed.insert(name);
  }
  for (const std::string &r : required)
    if (!listed.count(r)) throw InputError(sums_path + ": does not list " + r);
}

namespace {

// Along one axis: source samples and Q8 weights for each of `n` outputs from `m` inputs.
struct Tap {
  int first, count;       // shrinking: the source range [first, first + count) averaged
  int lo, hi, frac;       // growing: lo * (256 - frac) + hi * frac
};

std::vector<Tap> taps(int m, int n) {
  std::vector<Tap> t(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    if (n <= m) {
      // The footprint [i m / n, (i + 1) m / n), at least one source pixel.
      const int a = int(int64_t(i) * m / n), b = std::max(a + 1, int(int64_t(i + 1) * m / n));
      t[size_t(i)] = {a, b - a, 0, 0, 0};
    } else {
      // Pixel centres aligned: source x = (i + 1/2) m / n - 1/2, in 1/256 (2 n in the denominator).
      const int64_t q = (int64_t(2 * i + 1) * m - n) * 256 / (2 * int64_t(n));
      const int64_t qc = std::max<int64_t>(0, q);
      const int lo = std::min(m - 1, int(qc >> 8));
      t[size_t(i)] = {0, 0, lo, std::min(m - 1, lo + 1), int(qc & 255)};
    }
  }
  return t;
}

}  // namespace

Image resample_grey(const Image &src, int w, int h) {
  if (src.width == w && src.height == h) return src;
  const std::vector<Tap> tx = taps(src.width, w), ty = taps(src.height, h);
  const bool shrink_x = w <= src.width, shrink_y = h <= src.height;
  auto px = [&](int x, int y) { return int(src.data[size_t(y) * src.width + x]); };
  // One row of the source resampled in x, in 1/256 units when growing and as sums when shrinking.
  auto row = [&](int y, int x) -> int64_t {
    const Tap &t = tx[size_t(x)];
    if (shrink_x) {
      int64_t s = 0;
      for (int k = 0; k < t.count; ++k) s += px(t.first + k, y);
      return s;
    }
    return int64_t(px(t.lo, y)) * (256 - t.frac) + int64_t(px(t.hi, y)) * t.frac;
  };
  Image out(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Tap &t = ty[size_t(y)];
      int64_t num, den;
      if (shrink_y) {
        num = 0;
        for (int k = 0; k < t.count; ++k) num += row(t.first + k, x);
        den = int64_t(t.count);
      } else {
        num = row(t.lo, x) * (256 - t.frac) + row(t.hi, x) * t.frac;
        den = 256;
      }
      den *= shrink_x ? tx[size_t(x)].count : 256;
      out.data[size_t(y) * w + x] = uint8_t((num + den / 2) / den);
    }
  return out;
}

const BenchScene &bench_scene(int w, int h) {
  static std::mutex mu;
  static std::map<std::pair<int, int>, BenchScene> cache;
  std::lock_guard<std::mutex> lock(mu);
  auto it = cache.find({w, h});
  if (it != cache.end()) return it->second;
  std::string dir = bench_scene_dir(w, h);
  if (dir.empty()) dir = bench_scene_dir(320, 240);
  verify_sha256sums(dir, {"scene.txt", "truth.csv", "arena.txt", "frame_0000.pgm", "frame_0001.pgm"});
  const SceneData d = read_scene(dir);
  BenchScene s;
  s.truth = d.truth;
  if (w == d.camera.width && h == d.camera.height) {
    s.camera = d.camera;
  } else {
    // Resampling keeps the pixel centres aligned, which is what Camera::standard assumes for the
    // stored 320x240 frames; the mounting stays the stored camera's.
    s.camera = Camera::standard(w, h);
    s.camera.cam_height_in = d.camera.cam_height_in;
    s.camera.tilt_deg = d.camera.tilt_deg;
    s.camera.cam_offset_in = d.camera.cam_offset_in;
  }
  for (int k = 0; k < d.frames; ++k) s.grey.push_back(resample_grey(d.grey(k), w, h));
  return cache[{w, h}] = std::move(s);
}

}  // namespace bvb
