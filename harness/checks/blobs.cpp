// Check, bench and run for bvb/blobs.h (colour blobs on UYVY frames).
#include "bvb/blobs.h"

#include <algorithm>
#include <array>
#include <map>
#include <cstdio>
#include <cstring>
#include <sys/stat.h>

#include "family.h"
#include "io.h"
#include "patterns.h"
#include "robot_view.h"
#include "formats.h"
#include "names.h"

namespace bvb {
namespace {

// A UYVY frame from packed 4:2:2 bytes (2 * w per row), laid out with `stride` bytes per row and
// junk in the padding.
std::vector<uint8_t> with_stride(const std::vector<uint8_t> &packed, int w, int h, int stride, Rng &rng) {
  std::vector<uint8_t> d(size_t(stride) * (h - 1) + 2 * size_t(w));
  for (auto &v : d) v = uint8_t(rng.u32());
  for (int y = 0; y < h; ++y) std::memcpy(&d[size_t(y) * stride], &packed[size_t(y) * 2 * w], size_t(2) * w);
  return d;
}

std::vector<uint8_t> interleave(const std::vector<uint8_t> &Y, const std::vector<uint8_t> &U,
                                const std::vector<uint8_t> &V, int w, int h) {
  std::vector<uint8_t> p(size_t(2) * w * h);
  for (int y = 0; y < h; ++y)
    for (int k = 0; k < w / 2; ++k) {
      uint8_t *q = &p[(size_t(y) * w + 2 * k) * 2];
      q[0] = U[size_t(y) * (w / 2) + k];
      q[1] = Y[size_t(y) * w + 2 * k];
      q[2] = V[size_t(y) * (w / 2) + k];
      q[3] = Y[size_t(y) * w + 2 * k + 1];
    }
  return p;
}

// Rectangles and discs of a few palette colours on a background: real blobs, touching and
// nested, some diagonal-only contacts. Returns the palette (Y, U, V) used.
std::vector<uint8_t> blocky_frame(int w, int h, Rng &rng, std::vector<std::array<int, 3>> &palette) {
  palette.clear();
  const int ncol = rng.uniform(2, 6);
  for (int i = 0; i < ncol; ++i) palette.push_back({rng.uniform(0, 255), rng.uniform(0, 255), rng.uniform(0, 255)});
  std::vector<uint8_t> Y(size_t(w) * h), U(size_t(w / 2) * h), V(size_t(w / 2) * h);
  auto paint = [&](int x, int y, int c) {
    Y[size_t(y) * w + x] = uint8_t(palette[c][0]);
    U[size_t(y) * (w / 2) + x / 2] = uint8_t(palette[c][1]);
    V[size_t(y) * (w / 2) + x / 2] = uint8_t(palette[c][2]);
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) paint(x, y, 0);
  const int nshapes = rng.uniform(1, 12);
  for (int s = 0; s < nshapes; ++s) {
    const int c = rng.uniform(1, ncol - 1);
    const int x0 = rng.uniform(0, w - 1), y0 = rng.uniform(0, h - 1);
    const int rw = rng.uniform(1, std::max(1, w / 3)), rh = rng.uniform(1, std::max(1, h / 3));
    const bool disc = rng.uniform(0, 1);
    for (int y = y0; y < std::min(h, y0 + rh); ++y)
      for (int x = x0; x < std::min(w, x0 + rw); ++x) {
        if (disc) {
          const double dx = (x - x0 - rw / 2.0) / (rw / 2.0 + 0.5), dy = (y - y0 - rh / 2.0) / (rh / 2.0 + 0.5);
          if (dx * dx + dy * dy > 1) continue;
        }
        paint(x, y, c);
      }
  }
  // A diagonal staircase of single pixels: one blob with 8-connectivity, many with 4.
  const int c = rng.uniform(1, ncol - 1), x0 = rng.uniform(0, w - 1), y0 = rng.uniform(0, h - 1);
  for (int i = 0; x0 + i < w && y0 + i < h && i < 12; ++i) paint(x0 + i, y0 + i, c);
  return interleave(Y, U, V, w, h);
}

// Ranges around a palette colour, from exact to loose; the bounds themselves are in range.
bvb_blob_class class_around(const std::array<int, 3> &col, Rng &rng) {
  const int t = rng.uniform(0, 2) == 0 ? 0 : rng.uniform(1, 40);
  return {col[0] - t, col[0] + t, col[1] - t, col[1] + t, col[2] - t, col[2] + t};
}

bvb_blob_class random_class(Rng &rng) {
  int r[6];
  for (int ch = 0; ch < 3; ++ch) {
    int lo, hi;
    switch (rng.uniform(0, 6)) {
      case 0: lo = 0, hi = 255; break;
      case 1: lo = hi = rng.uniform(0, 255); break;                   // a single value
      case 2: lo = rng.uniform(1, 255), hi = rng.uniform(0, lo - 1); break;  // empty
      case 3: lo = rng.uniform(-300, 0), hi = rng.uniform(255, 600); break;  // beyond 0..255
      default: lo = rng.uniform(0, 255), hi = std::min(255, lo + rng.uniform(0, 160));
    }
    r[2 * ch] = lo, r[2 * ch + 1] = hi;
  }
  return {r[0], r[1], r[2], r[3], r[4], r[5]};
}

CheckCall blobs_call(std::vector<uint8_t> uyvy, int w, int h, int stride, const bvb_blob_params &prm,
                     int label_cap, const std::string &case_name) {
  CheckCall c;
  c.kernel = "blobs_uyvy";
  c.case_name = case_name;
  c.pixels = double(w) * h;
  const int nout = std::max(0, std::min(prm.nclasses, 8)) * std::max(prm.max_blobs, 0);
  int iu = c.in("uyvy", std::move(uyvy), View{1, false, 2 * w, h, stride});
  int ip = c.in("params", bytes_of(prm), View{4, true});
  int ib = c.out("blobs", size_t(std::max(nout, 1)) * sizeof(bvb_blob), View{4, true, 8, std::max(nout, 1), 8});
  int is = c.out("summary", sizeof(bvb_blob_summary), View{4, true});
  int ix = c.scratch("scratch", size_t(BVB_BLOBS_SCRATCH_BYTES(w, label_cap)));
  c.buf(iu).word(stride).word(w).word(h).buf(ip).buf(ib).buf(is).buf(ix).word(label_cap);
  c.host = [=](HostBuffers &m) {
    std::vector<uint32_t> scratch(size_t(BVB_BLOBS_SCRATCH_BYTES(w, label_cap)) / 4 + 1);
    bvb_blobs_uyvy_c(m.u8(iu), stride, w, h, m.as<bvb_blob_params>(ip), m.as<bvb_blob>(ib),
                     m.as<bvb_blob_summary>(is), scratch.data(), label_cap);
  };
  return c;
}

// Skews each buffer as its element type allows, then places them all together.
void place_buffers(Checker &ck, CheckCall &c, Rng &rng) {
  for (auto &b : c.bufs) {
    if (b.name == "uyvy") b.skew = uint32_t(rng.uniform(0, 3));  // byte data: no alignment needed
  }
  ck.place_randomly(c);
}

// A colour crop of a real frame (RubberWhale or Dimetrodon, the colour frames of frames-real) as
// UYVY; empty when the frames are not there.
std::vector<uint8_t> real_uyvy(const std::string &dir, int w, int h, Rng &rng) {
  static const char *frames[] = {"RubberWhale/frame10.ppm", "Dimetrodon/frame10.ppm"};
  const std::string path = dir + "/" + frames[rng.uniform(0, 1)];
  struct stat st;
  if (dir.empty() || stat(path.c_str(), &st) != 0) return {};
  static std::map<std::string, Image> cache;
  if (!cache.count(path)) cache[path] = read_pnm(path);
  const Image &src = cache[path];
  Image crop(w, h, 3);
  const int x0 = src.width > w ? rng.uniform(0, src.width - w) : 0;
  const int y0 = src.height > h ? rng.uniform(0, src.height - h) : 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int ch = 0; ch < 3; ++ch)
        crop.at(x, y, ch) = src.at((x0 + x) % src.width, (y0 + y) % src.height, ch);
  return rgb_to_uyvy(crop);
}

// The robot's colour classes in the boxes arena (BT.601 studio range, render.h): the red boxes
// (170, 35, 30) have V well above the floor's ~140, the blue box (40, 60, 180) U well above its
// ~113, whatever the lighting.
const bvb_blob_class kRed{0, 255, 0, 255, 160, 255};
const bvb_blob_class kBlue{0, 255, 150, 255, 0, 255};

bvb_blob_params robot_params() {
  bvb_blob_params p{};
  p.nclasses = 2, p.connectivity = 8, p.max_blobs = 8, p.min_count = 8;
  p.cls[0] = kRed, p.cls[1] = kBlue;
  return p;
}

void check(Checker &ck) {
  Rng &rng = ck.rng();
  for (Size s0 : check_sizes(2, 1, rng, ck.options().campaign)) {
    const Size s{s0.w + (s0.w & 1), s0.h};
    for (Pattern pat : ck.patterns()) {
      const int stride = pick_stride(2 * s.w, rng);
      bvb_blob_params prm{};
      prm.nclasses = rng.uniform(1, 8);
      prm.connectivity = rng.uniform(0, 1) ? 8 : 4;
      prm.max_blobs = rng.uniform(0, 3) == 0 ? 1 : rng.uniform(1, 10);
      prm.min_count = rng.uniform(0, 2) == 0 ? 1 : rng.uniform(1, 6);
      std::vector<uint8_t> packed;
      std::string src;
      const int kind = pat == Pattern::Real ? rng.uniform(0, 1) * 3 : rng.uniform(0, 2);
      if (kind == 0) {
        // Blocks of palette colours with classes around some of them.
        std::vector<std::array<int, 3>> pal;
        packed = blocky_frame(s.w, s.h, rng, pal);
        for (int c = 0; c < prm.nclasses; ++c)
          prm.cls[c] = rng.uniform(0, 3) ? class_around(pal[rng.uniform(0, int(pal.size()) - 1)], rng) : random_class(rng);
        src = "blocks";
      } else if (kind == 3) {
        packed = real_uyvy(ck.options().frames_real, s.w, s.h, rng);
        for (int c = 0; c < prm.nclasses; ++c) prm.cls[c] = random_class(rng);
        src = "real colour";
      }
      if (packed.empty()) {
        // Y, U and V planes from the crafted patterns.
        const Pattern pu = ck.patterns()[rng.uniform(0, int(ck.patterns().size()) - 1)];
        const Pattern pv = ck.patterns()[rng.uniform(0, int(ck.patterns().size()) - 1)];
        const std::string &fr = ck.options().frames_real;
        packed = interleave(make_plane(pat, s.w, s.h, s.w, rng, fr), make_plane(pu, s.w / 2, s.h, s.w / 2, rng, fr),
                            make_plane(pv, s.w / 2, s.h, s.w / 2, rng, fr), s.w, s.h);
        for (int c = 0; c < prm.nclasses; ++c) prm.cls[c] = random_class(rng);
        src = std::string("planes ") + pattern_name(pat) + "/" + pattern_name(pu) + "/" + pattern_name(pv);
      }
      // Half the classes are built around the colour of a pixel of the frame, so they hold
      // something whatever the frame.
      for (int c = 0; c < prm.nclasses; ++c) {
        if (rng.uniform(0, 1)) continue;
        const int x = rng.uniform(0, s.w - 1), y = rng.uniform(0, s.h - 1);
        const uint8_t *q = &packed[(size_t(y) * s.w + (x & ~1)) * 2];
        prm.cls[c] = class_around({q[1 + 2 * (x & 1)], q[0], q[2]}, rng);
      }
      const int full = s.w * s.h;
      const int r = rng.uniform(0, 4);
      const int cap = r == 0 ? rng.uniform(0, 16) : r == 1 ? full / 64 + 1 : std::min(full, 32768);
      std::string name = size_name(s.w, s.h) + " stride " + std::to_string(stride) +
                         " " + src + " classes " + std::to_string(prm.nclasses) + " conn " +
                         std::to_string(prm.connectivity) + " max " + std::to_string(prm.max_blobs) + " min " +
                         std::to_string(prm.min_count) + " labels " + std::to_string(cap);
      CheckCall c = blobs_call(with_stride(packed, s.w, s.h, stride, rng), s.w, s.h, stride, prm, cap, name);
      place_buffers(ck, c, rng);
      ck.add(std::move(c));
    }
  }
  for (Size s : std::vector<Size>{{160, 120}, {80, 60}, {162, 121}}) {
    for (int pose = 0; pose < 4; ++pose) {
      bvb_blob_params prm = robot_params();
      prm.connectivity = pose & 1 ? 4 : 8;
      const auto &uyvy = robot_view(s.w, s.h, pose).uyvy;
      ck.add(blobs_call(uyvy, s.w, s.h, 2 * s.w, prm, 4096,
                        size_name(s.w, s.h) + " robot view " + std::to_string(pose) +
                            " conn " + std::to_string(prm.connectivity)));
    }
  }
}

CheckCall bench_call(const std::string &, int w, int h, Rng &) {
  if (w & 1) return {};
  return blobs_call(robot_view(w, h, 0).uyvy, w, h, 2 * w, robot_params(), 8192,
                    size_name(w, h));
}

// --param classN=YMIN:YMAX:UMIN:UMAX:VMIN:VMAX for N = 0, 1, ... (contiguous); without any,
// the robot's red and blue.
bvb_blob_params run_params(Params &ps) {
  bvb_blob_params p = robot_params();
  int n = 0;
  for (; n < BVB_BLOBS_MAX_CLASSES; ++n) {
    const std::string key = "class" + std::to_string(n);
    if (!ps.has(key)) break;
    const std::string v = ps.get_str(key, "");
    int r[6];
    char tail;
    if (std::sscanf(v.c_str(), "%d:%d:%d:%d:%d:%d%c", &r[0], &r[1], &r[2], &r[3], &r[4], &r[5], &tail) != 6)
      throw InputError("parameter " + key + "=" + v + ": want YMIN:YMAX:UMIN:UMAX:VMIN:VMAX");
    p.cls[n] = {r[0], r[1], r[2], r[3], r[4], r[5]};
  }
  if (n > 0) {
    p.nclasses = n;
    for (int k = n; k < BVB_BLOBS_MAX_CLASSES; ++k) p.cls[k] = {};
  }
  p.connectivity = ps.get_int("conn", 8, 4, 8);
  if (p.connectivity != 4 && p.connectivity != 8) throw InputError("blobs_uyvy: conn must be 4 or 8");
  p.max_blobs = ps.get_int("max_blobs", 8, 1, 1000);
  p.min_count = ps.get_int("min_count", 8, 1, 1 << 30);
  return p;
}

// Input: a PPM (converted to UYVY as the camera would deliver it), a raw .uyvy (--size), or a
// PGM (U = V = 128). Output: .txt or .csv gets one line per blob; anything else a PPM of the
// frame with each blob's bounding box drawn in its class's colour.
RunPlan plan_run(RunRequest &req) {
  if (req.inputs.size() != 1) throw InputError("blobs_uyvy takes one --in frame");
  const std::string &in = req.inputs[0];
  std::vector<uint8_t> uyvy;
  Image rgb;
  int w, h;
  if (format_of(in) == FileFormat::Uyvy) {
    if (req.raw_width <= 0 || req.raw_height <= 0) throw InputError(in + ": raw UYVY input needs --size WxH");
    w = req.raw_width, h = req.raw_height;
    uyvy = read_uyvy(in, w, h);
  } else {
    Image img = read_image(in);
    if (img.width < 2) throw InputError(in + ": blobs_uyvy needs a frame at least 2 pixels wide");
    w = img.width & ~1, h = img.height;  // UYVY pairs pixels: an odd last column is left out
    rgb = Image(w, h, 3);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int ch = 0; ch < 3; ++ch) rgb.at(x, y, ch) = img.at(x, y, img.channels == 3 ? ch : 0);
    if (img.channels == 3) {
      uyvy = rgb_to_uyvy(rgb);
    } else {
      uyvy.assign(size_t(2) * w * h, 128);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) uyvy[(size_t(y) * w + x) * 2 + 1] = img.at(x, y);
    }
  }
  if (double(w) * h * std::max(w, h) >= 2147483648.0)
    throw InputError("blobs_uyvy: frame too large (width * height * max(width, height) must stay below 2^31)");
  const bvb_blob_params prm = run_params(req.params);
  const int cap = req.params.get_int("labels", std::min(w * h, 65536), 0, w * h);
  req.params.check_all_used();
  if (rgb.data.empty()) {  // from UYVY: show the Y plane
    rgb = Image(w, h, 3);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int ch = 0; ch < 3; ++ch) rgb.at(x, y, ch) = uyvy[(size_t(y) * w + x) * 2 + 1];
  }
  RunPlan p;
  p.call = blobs_call(uyvy, w, h, 2 * w, prm, cap, "run");
  const int nout = prm.nclasses * prm.max_blobs;
  p.write = [rgb, nout](std::vector<std::vector<uint8_t>> &bufs, const std::string &path) {
    std::vector<bvb_blob> blobs(static_cast<size_t>(nout));
    std::memcpy(blobs.data(), bufs[2].data(), blobs.size() * sizeof(bvb_blob));
    bvb_blob_summary sum;
    std::memcpy(&sum, bufs[3].data(), sizeof sum);
    const bool text = format_of(path) == FileFormat::Text;
    if (text) {
      std::string s = "class,count,min_x,min_y,max_x,max_y,centroid_x,centroid_y\n";
      char line[200];
      for (const auto &b : blobs) {
        if (!b.count) continue;
        std::snprintf(line, sizeof line, "%d,%d,%d,%d,%d,%d,%.2f,%.2f\n", b.cls, b.count, b.min_x, b.min_y,
                      b.max_x, b.max_y, double(b.sum_x) / b.count, double(b.sum_y) / b.count);
        s += line;
      }
      write_text_output(path, s);
    } else {
      static const uint8_t colours[8][3] = {{255, 0, 0},   {0, 80, 255},  {0, 220, 0},   {255, 220, 0},
                                            {255, 0, 255}, {0, 230, 230}, {255, 128, 0}, {255, 255, 255}};
      Image out = rgb;
      for (const auto &b : blobs) {
        if (!b.count) continue;
        auto dot = [&](int x, int y) {
          for (int ch = 0; ch < 3; ++ch) out.at(x, y, ch) = colours[b.cls & 7][ch];
        };
        for (int x = b.min_x; x <= b.max_x; ++x) dot(x, b.min_y), dot(x, b.max_y);
        for (int y = b.min_y; y <= b.max_y; ++y) dot(b.min_x, y), dot(b.max_x, y);
      }
      write_image(path, out);
    }
    int found = 0;
    for (int c = 0; c < BVB_BLOBS_MAX_CLASSES; ++c) found += sum.found[c];
    std::printf("blobs: %d found, %d labels used, %d pixels dropped\n", found, sum.labels_used, sum.dropped);
  };
  p.kind = OutputKind::ImageOrText;
  p.summary = size_name(w, h) + " " + std::to_string(prm.nclasses) + " classes";
  return p;
}

const Family kBlobs{"blobs", {"blobs_uyvy"}, check, bench_call, nullptr, plan_run};
BVB_FAMILY(kBlobs);

}  // namespace
}  // namespace bvb
