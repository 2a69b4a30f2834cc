// Check, bench and run for bvb/harris.h: harris_response (C and assembly) and harris_corners
// (C only).
//
// Why harris_corners has no assembly: it reads the response map once (one load and one compare
// per pixel for the pixels below the threshold, which is nearly all of them) and sorts a few
// hundred candidates. bfbench bench measures it next to harris_response on the same real
// frames (the numbers are in firmware/asm/harris.S).
#include "bvb/harris.h"

#include <algorithm>
#include <cstring>

#include "family.h"
#include "io.h"
#include "patterns.h"

namespace bvb {
namespace {

const uint32_t kPlaces[] = {BVB_PLACE_SDRAM, BVB_PLACE_L1A, BVB_PLACE_L1B, BVB_PLACE_SCRATCH};

size_t room(uint32_t place) {
  return place == BVB_PLACE_SCRATCH ? 4096u : place == BVB_PLACE_L1B ? 24576u : 32768u;
}

// Puts each buffer in `place` when it fits there (with what is already there), else in SDRAM.
void place_buffers(CheckCall &c, uint32_t place) {
  size_t used = 0;
  for (auto &b : c.bufs) {
    const size_t need = b.data.size() + 2 * b.guard + b.align + 8;
    if (used + need <= room(place)) {
      b.place = place;
      used += need;
    } else {
      b.place = BVB_PLACE_SDRAM;
    }
  }
}

std::vector<uint8_t> as_bytes(const std::vector<int32_t> &v) {
  std::vector<uint8_t> b(v.size() * 4);
  std::memcpy(b.data(), v.data(), b.size());
  return b;
}

CheckCall response_call(int w, int h, int sstride, int dstride, std::vector<uint8_t> src,
                        const std::string &case_name) {
  CheckCall c;
  c.kernel = "harris_response";
  c.case_name = case_name;
  c.pixels = double(w) * h;
  int is = c.in("src", std::move(src), View{1, false, w, h, sstride});
  int id = c.out("resp", (size_t(dstride) * (h - 1) + w) * 4, View{4, true, w, h, dstride});
  int iscr = c.scratch("scratch", BVB_HARRIS_SCRATCH_BYTES(w));
  c.buf(is).buf(id).word(w).word(h).word(sstride).word(dstride).buf(iscr);
  c.host = [=](HostBuffers &m) {
    bvb_harris_response_c(m.u8(is), m.s32(id), w, h, sstride, dstride, m.u8(iscr));
  };
  return c;
}

// Stripes of period 4 that keep |gx| = |gy| = 255 everywhere: the extremes of every bound in
// bvb/harris.h (kind 0: a = b = max; 1: c = max; 2: c = min).
std::vector<uint8_t> stripes(int kind, int w, int h, int stride) {
  std::vector<uint8_t> d(size_t(stride) * (h - 1) + w, 0x5A);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      bool on = kind == 0 ? ((x & 3) < 2) != ((y & 3) < 2) : kind == 1 ? ((x + y) & 3) < 2 : ((x - y) & 3) < 2;
      d[size_t(y) * stride + x] = on ? 255 : 0;
    }
  return d;
}

std::vector<int32_t> host_response(const std::vector<uint8_t> &img, int w, int h, int stride) {
  std::vector<int32_t> r(size_t(w) * h);
  std::vector<uint8_t> scratch(BVB_HARRIS_SCRATCH_BYTES(w));
  bvb_harris_response_c(img.data(), r.data(), w, h, stride, w, scratch.data());
  return r;
}

CheckCall corners_call(int w, int h, int stride, std::vector<int32_t> resp, int32_t threshold,
                       int32_t max_corners, int32_t min_distance, const std::string &case_name) {
  CheckCall c;
  c.kernel = "harris_corners";
  c.case_name = case_name;
  c.pixels = double(w) * h;
  int ir = c.in("resp", as_bytes(resp), View{4, true, w, h, stride});
  int io = c.out("corners", size_t(std::max(1, max_corners)) * 12, View{4, true, 3, std::max(1, max_corners), 3});
  int iscr = c.scratch("scratch", BVB_HARRIS_CORNERS_SCRATCH_BYTES(w, h));
  c.buf(ir).word(w).word(h).word(stride).word(threshold).word(max_corners).word(min_distance).buf(io).buf(iscr);
  // The count returned is not compared; the entries after the last corner taken keep the
  // output's poison pattern, so a wrong count shows as a difference there.
  c.host = [=](HostBuffers &m) {
    bvb_harris_corners_c(m.s32(ir), w, h, stride, threshold, max_corners, min_distance, m.s32(io), m.u8(iscr));
  };
  return c;
}

void check(Checker &ck) {
  Rng &rng = ck.rng();
  const std::string &frames = ck.options().frames_real;
  if (ck.wants("harris_response")) {
    for (Size s : check_sizes(5, 5, rng, ck.options().campaign)) {
      std::vector<std::pair<std::string, std::vector<uint8_t>>> inputs;
      const int ss = pick_stride(s.w, rng), ds = pick_stride(s.w, rng);
      for (Pattern p : all_patterns()) inputs.push_back({pattern_name(p), make_plane(p, s.w, s.h, ss, rng, frames)});
      for (int k = 0; k < 3; ++k) inputs.push_back({"stripes" + std::to_string(k), stripes(k, s.w, s.h, ss)});
      for (auto &in : inputs) {
        std::string name = std::to_string(s.w) + "x" + std::to_string(s.h) + " strides " + std::to_string(ss) +
                           "/" + std::to_string(ds) + " " + in.first;
        CheckCall c = response_call(s.w, s.h, ss, ds, std::move(in.second), name);
        place_buffers(c, kPlaces[rng.uniform(0, 3)]);
        c.bufs[0].skew = uint32_t(rng.uniform(0, 3));  // the source has no alignment contract
        ck.add(std::move(c));
      }
    }
  }
  if (ck.wants("harris_corners")) {
    for (Size s : check_sizes(3, 3, rng, ck.options().campaign)) {
      for (int variant = 0; variant < 4; ++variant) {
        const int stride = pick_stride(s.w, rng);
        std::vector<int32_t> resp(size_t(stride) * (s.h - 1) + s.w);
        std::string what;
        if (variant < 2 && s.w >= 5 && s.h >= 5) {
          // Responses of real frames and of noise.
          Pattern p = variant == 0 ? Pattern::Real : Pattern::Noise;
          auto img = make_plane(p, s.w, s.h, s.w, rng, frames);
          auto r = host_response(img, s.w, s.h, s.w);
          for (int y = 0; y < s.h; ++y)
            for (int x = 0; x < s.w; ++x) resp[size_t(y) * stride + x] = r[size_t(y) * s.w + x];
          what = pattern_name(p);
        } else {
          // Few distinct values: plateaus and ties everywhere; negative values too.
          const int levels = variant == 2 ? 3 : 40;
          for (auto &v : resp) v = int32_t(rng.uniform(-1, levels));
          what = "levels" + std::to_string(levels);
        }
        int32_t maxv = 0;
        for (int32_t v : resp) maxv = std::max(maxv, v);
        const int32_t threshold = variant >= 2 ? rng.uniform(0, 1) : maxv / rng.uniform(20, 400);
        const int32_t max_corners = rng.uniform(0, 3) == 0 ? rng.uniform(0, 3) : rng.uniform(1, 64);
        const int32_t min_distance = rng.uniform(0, 12);
        std::string name = std::to_string(s.w) + "x" + std::to_string(s.h) + " stride " + std::to_string(stride) +
                           " " + what + " thr " + std::to_string(threshold) + " max " +
                           std::to_string(max_corners) + " dist " + std::to_string(min_distance);
        CheckCall c = corners_call(s.w, s.h, stride, std::move(resp), threshold, max_corners, min_distance, name);
        place_buffers(c, kPlaces[rng.uniform(0, 3)]);
        ck.add(std::move(c));
      }
    }
  }
}

// The bench frames: a real crop (tiled above 640x480), the same for both kernels.
std::vector<uint8_t> bench_frame(int w, int h, Rng &rng) {
  return make_plane(Pattern::Real, w, h, w, rng, default_frames_real());
}

CheckCall bench_call(const std::string &kernel, int w, int h, Rng &rng) {
  const std::string size = std::to_string(w) + "x" + std::to_string(h);
  auto img = bench_frame(w, h, rng);
  if (kernel == "harris_response") return response_call(w, h, w, w, std::move(img), size);
  auto resp = host_response(img, w, h, w);
  int32_t maxv = 0;
  for (int32_t v : resp) maxv = std::max(maxv, v);
  // A robot's setting: the 32 strongest corners at least 8 pixels apart, above 1% of the peak.
  return corners_call(w, h, w, std::move(resp), maxv / 100, 32, 8, size);
}

// harris_response, per pixel: the gradients (two byte differences per pixel, four pixels per
// BYTEOP16M, and the x32 scaling: 1.0 issue), the three 3-row column sums (9 products:
// 4.5 dual-MAC issues), the three 3-column window sums (6 16-bit adds on pairs: 3.0 issues) and
// the response (2 multiplies and 3 MACs on pairs: 2.5 issues). Loads and stores fit the free
// slots. 11 issues per pixel.
double lower_bound(const std::string &kernel, int w, int h) {
  if (kernel != "harris_response") return 0;
  return 11.0 * w * h;
}

RunPlan plan_run(RunRequest &req) {
  if (req.inputs.size() != 1) throw InputError(req.kernel + " takes one --in frame");
  Image a = read_frame(req.inputs[0], req.raw_width, req.raw_height);
  if (a.width < 5 || a.height < 5) throw InputError(req.kernel + ": the frame must be at least 5x5");
  const int w = a.width, h = a.height;
  RunPlan p;
  if (req.kernel == "harris_response") {
    req.params.check_all_used();
    p.call = response_call(w, h, w, w, a.data, "run");
    // The positive response (corners), scaled so that the strongest is white.
    p.write = [w, h](std::vector<std::vector<uint8_t>> &bufs, const std::string &path) {
      std::vector<int32_t> r(size_t(w) * h);
      std::memcpy(r.data(), bufs[1].data(), r.size() * 4);
      int32_t maxv = 1;
      for (int32_t v : r) maxv = std::max(maxv, v);
      Image out(w, h);
      for (size_t i = 0; i < r.size(); ++i) out.data[i] = uint8_t(std::max<int64_t>(0, int64_t(r[i]) * 255 / maxv));
      write_pnm(path, out);
    };
    p.summary = std::to_string(w) + "x" + std::to_string(h) + ", response (positive part, scaled to the peak)";
    return p;
  }
  const int percent = req.params.get_int("threshold_permille", 10, 0, 1000);
  const int max_corners = req.params.get_int("max", 32, 0, 4096);
  const int dist = req.params.get_int("distance", 8, 0, 1000);
  req.params.check_all_used();
  auto resp = host_response(a.data, w, h, w);
  int32_t maxv = 0;
  for (int32_t v : resp) maxv = std::max(maxv, v);
  const int32_t thr = int32_t(int64_t(maxv) * percent / 1000);
  p.call = corners_call(w, h, w, std::move(resp), thr, max_corners, dist, "run");
  std::fill(p.call.bufs[1].data.begin(), p.call.bufs[1].data.end(), 0xFF);  // x = -1 ends the list
  // The frame with a cross on each corner taken.
  p.write = [a, max_corners](std::vector<std::vector<uint8_t>> &bufs, const std::string &path) {
    Image out = a;
    const int32_t *c = reinterpret_cast<const int32_t *>(bufs[1].data());
    for (int k = 0; k < max_corners; ++k) {
      const int x = c[3 * k], y = c[3 * k + 1];
      if (x < 0 || y < 0 || x >= out.width || y >= out.height) break;
      for (int d = -3; d <= 3; ++d) {
        if (x + d >= 0 && x + d < out.width) out.at(x + d, y) = 255;
        if (y + d >= 0 && y + d < out.height) out.at(x, y + d) = 255;
      }
    }
    write_pnm(path, out);
  };
  p.summary = std::to_string(w) + "x" + std::to_string(h) + ", corners above " + std::to_string(thr) +
              " marked with crosses";
  return p;
}

const Family kHarris{"harris", {"harris_response", "harris_corners"}, check, bench_call, lower_bound, plan_run};
BVB_FAMILY(kHarris);

}  // namespace
}  // namespace bvb
