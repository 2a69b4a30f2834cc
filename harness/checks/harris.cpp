// Check, bench and run for bvb/harris.h: harris_response and harris_nms (C and assembly),
// harris_select (C only).
//
// Why harris_nms has assembly although it is "only" a scan: in C it reads and compares every
// pixel with a branch the compiler lays out as taken, about 16 cycles per pixel on real frames
// at a 1% threshold, more than the assembly response. Why harris_select has none: it works on
// the candidates (a few hundred to a few thousand), not on the pixels; the bench below measures
// it on the candidates of the same real frames.
#include "bvb/harris.h"

#include <algorithm>
#include <cstring>

#include "family.h"
#include "io.h"
#include "patterns.h"
#include "names.h"

namespace bvb {
namespace {

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

CheckCall nms_call(int w, int h, int stride, std::vector<int32_t> resp, int32_t threshold,
                   const std::string &case_name) {
  CheckCall c;
  c.kernel = "harris_nms";
  c.case_name = case_name;
  c.pixels = double(w) * h;
  const int cap = BVB_HARRIS_NMS_CAPACITY(w, h);
  int ir = c.in("resp", as_bytes(resp), View{4, true, w, h, stride});
  int io = c.out("cand", size_t(cap) * 8, View{4, true, 2, cap, 2});
  int in = c.out("count", 4, View{4, true});
  int is = c.scratch("scratch", BVB_HARRIS_NMS_STREAM_SCRATCH_BYTES(w));
  c.buf(ir).word(w).word(h).word(stride).word(threshold).buf(io).buf(in).buf(is);
  c.host = [=](HostBuffers &m) {
    m.set_ret(bvb_harris_nms_c(m.s32(ir), w, h, stride, threshold, m.s32(io), m.s32(in), m.u8(is)));
  };
  return c;
}

std::vector<int32_t> host_nms(const std::vector<int32_t> &resp, int w, int h, int stride, int32_t threshold) {
  std::vector<int32_t> cand(size_t(BVB_HARRIS_NMS_CAPACITY(w, h)) * 2);
  int32_t n = 0;
  bvb_harris_nms_c(resp.data(), w, h, stride, threshold, cand.data(), &n, nullptr);
  cand.resize(size_t(n) * 2);
  return cand;
}

CheckCall select_call(std::vector<int32_t> cand, int32_t max_corners, int32_t min_distance,
                      const std::string &case_name, double pixels) {
  CheckCall c;
  c.kernel = "harris_select";
  c.case_name = case_name;
  c.pixels = pixels;
  const int n = int(cand.size() / 2);
  cand.push_back(int32_t(0x5EED5EED));  // the room for the heap's sentinel
  cand.push_back(int32_t(0x5EED5EED));
  int ic = c.inout("cand", as_bytes(cand), View{4, true, 2, n + 1, 2});
  int io = c.out("corners", size_t(std::max(1, max_corners)) * 12, View{4, true, 3, std::max(1, max_corners), 3});
  c.buf(ic).word(n).word(max_corners).word(min_distance).buf(io);
  // The count returned is not compared; the entries after the last corner taken keep the
  // output's poison pattern, so a wrong count shows there.
  c.host = [=](HostBuffers &m) { m.set_ret(bvb_harris_select_c(m.s32(ic), n, max_corners, min_distance, m.s32(io))); };
  return c;
}

// Response maps to pick corners from: of real frames, of noise, and maps of a few distinct
// values (plateaus and ties everywhere, negative values too).
std::vector<int32_t> test_map(int variant, int w, int h, int stride, Rng &rng, const std::string &frames,
                              std::string &what) {
  std::vector<int32_t> resp(size_t(stride) * (h - 1) + w);
  for (auto &v : resp) v = int32_t(rng.u32() | 0x80000001u);  // row padding: must not be read
  if (variant < 2 && w >= 5 && h >= 5) {
    Pattern p = variant == 0 ? Pattern::Real : Pattern::Noise;
    auto img = make_plane(p, w, h, w, rng, frames);
    auto r = host_response(img, w, h, w);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) resp[size_t(y) * stride + x] = r[size_t(y) * w + x];
    what = pattern_name(p);
  } else {
    const int levels = variant == 2 ? 3 : 40;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) resp[size_t(y) * stride + x] = int32_t(rng.uniform(-1, levels));
    what = "levels" + std::to_string(levels);
  }
  return resp;
}

void check(Checker &ck) {
  Rng &rng = ck.rng();
  const std::string &frames = ck.options().frames_real;
  {
    for (Size s : check_sizes(5, 5, rng, ck.options().campaign)) {
      std::vector<std::pair<std::string, std::vector<uint8_t>>> inputs;
      const int ss = pick_stride(s.w, rng), ds = pick_stride(s.w, rng);
      for (Pattern p : ck.patterns()) inputs.push_back({pattern_name(p), make_plane(p, s.w, s.h, ss, rng, frames)});
      for (int k = 0; k < 3; ++k) inputs.push_back({"stripes" + std::to_string(k), stripes(k, s.w, s.h, ss)});
      for (auto &in : inputs) {
        std::string name = size_name(s.w, s.h) + " strides " + std::to_string(ss) +
                           "/" + std::to_string(ds) + " " + in.first;
        CheckCall c = response_call(s.w, s.h, ss, ds, std::move(in.second), name);
        // Half the calls where the robot runs it (the assembly's DMA path); a third of those with
        // the response in the other L1 bank where it fits, as the odometry's strips take it (the
        // core writes the rows there, the DMA brings only the image rows).
        ck.place_streaming(c, 2, rng);
        if (c.bufs[0].place == BVB_PLACE_SDRAM && c.bufs[2].place != BVB_PLACE_SDRAM && rng.uniform(0, 2) == 0) {
          const uint32_t other = c.bufs[2].place == BVB_PLACE_L1A ? BVB_PLACE_L1B : BVB_PLACE_L1A;
          if (c.bufs[1].data.size() + 2 * c.bufs[1].guard + c.bufs[1].align <= ck.target().arena_bytes(other)) {
            c.bufs[1].place = other;
            c.case_name += ", response in L1";
          }
        }
        c.bufs[0].skew = uint32_t(rng.uniform(0, 3));  // the source has no alignment contract
        ck.add(std::move(c));
      }
    }
  }
  {
    for (Size s : check_sizes(3, 3, rng, ck.options().campaign)) {
      for (int variant = 0; variant < 4; ++variant) {
        if (variant == 0 && !ck.have_frames()) {  // a real frame's response map
          ck.skip_real();
          continue;
        }
        const int stride = pick_stride(s.w, rng);
        std::string what;
        std::vector<int32_t> resp = test_map(variant, s.w, s.h, stride, rng, frames, what);
        int32_t maxv = 0;
        for (int y = 0; y < s.h; ++y)
          for (int x = 0; x < s.w; ++x) maxv = std::max(maxv, resp[size_t(y) * stride + x]);
        const int32_t threshold = variant >= 2 ? rng.uniform(0, 1) : maxv / rng.uniform(20, 400);
        const std::string base = size_name(s.w, s.h) + " stride " +
                                 std::to_string(stride) + " " + what + " thr " + std::to_string(threshold);
        {
          const int32_t max_corners = rng.uniform(0, 3) == 0 ? rng.uniform(0, 3) : rng.uniform(1, 64);
          const int32_t min_distance = rng.uniform(0, 12);
          CheckCall c = select_call(host_nms(resp, s.w, s.h, stride, threshold), max_corners, min_distance,
                                    base + " max " + std::to_string(max_corners) + " dist " +
                                        std::to_string(min_distance),
                                    double(s.w) * s.h);
          ck.place_randomly(c);
          ck.add(std::move(c));
        }
        {
          CheckCall c = nms_call(s.w, s.h, stride, std::move(resp), threshold, base);
          // Half the calls where the robot's stand-alone scan runs (the map streamed through L1).
          ck.place_streaming(c, 3, rng);
          ck.add(std::move(c));
        }
      }
    }
  }
}

// The bench frames: the integer texture (patterns.h), the same bytes on every host and for the
// three kernels, so that the budgets depend on nothing outside the repository.
std::vector<uint8_t> bench_frame(int w, int h, Rng &) { return hermetic_texture(w, h, 0x4841525249530001ull).data; }

// A robot's setting for the corner kernels: candidates above 1% of the peak response (OpenCV's
// default quality level), the 32 strongest at least 8 pixels apart.
CheckCall bench_call(const std::string &kernel, int w, int h, Rng &rng) {
  const std::string size = size_name(w, h);
  auto img = bench_frame(w, h, rng);
  if (kernel == "harris_response") {
    // Frames in SDRAM, the scratch (6.4 KB at 160, 23.7 KB at 640) in L1 bank B.
    CheckCall c = response_call(w, h, w, w, std::move(img), size);
    c.bufs[2].place = BVB_PLACE_L1B;
    return c;
  }
  auto resp = host_response(img, w, h, w);
  int32_t maxv = 0;
  for (int32_t v : resp) maxv = std::max(maxv, v);
  if (kernel == "harris_nms") {
    // The map in SDRAM, the scratch (23.0 KB at 320 wide) in L1 bank B: the rows stream in.
    // At 640 wide it (42 KB) does not fit the bank's 24 KB arena, and the scan reads the map in place.
    CheckCall c = nms_call(w, h, w, std::move(resp), maxv / 100, size);
    if (BVB_HARRIS_NMS_STREAM_SCRATCH_BYTES(w) <= 24 * 1024) c.bufs[3].place = BVB_PLACE_L1B;
    return c;
  }
  auto cand = host_nms(resp, w, h, w, maxv / 100);
  return select_call(std::move(cand), 32, 8, size + " " + std::to_string(cand.size() / 2) + " cand", double(w) * h);
}

// harris_response, per pixel: the gradients (two differences per pixel at four per BYTEOP16M:
// 0.5, and their x32 scaling at two per vector shift: 1.0), the three 3-row column sums (9
// products: 4.5 dual-MAC issues), the three 3-column window sums (2 vector adds per pair and
// sum: 3.0) and the response (hh, kh and three dual MACs per pair: 2.5): 11.5 issues per pixel.
// harris_nms: every value goes through the one 32-bit ALU at least once (a MAX tree and a
// compare per block of values): 1 issue per pixel, whatever the candidates cost on top; with
// the map in SDRAM (the bench's placement) its 4 bytes per pixel take the bus 8 cycles at 0.5
// byte per core cycle, the longer of the two.
double lower_bound(const std::string &kernel, int w, int h) {
  if (kernel == "harris_response") return 11.5 * w * h;
  if (kernel == "harris_nms") return 8.0 * w * h;
  return 0;
}

RunPlan plan_run(RunRequest &req) {
  if (req.inputs.size() != 1) throw InputError(req.kernel + " takes one --in frame");
  Image a = read_input(req, 0);
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
      write_image(path, out);
    };
    p.summary = size_name(w, h) + ", response (positive part, scaled to the peak)";
    return p;
  }
  const int permille = req.params.get_int("threshold_permille", 10, 0, 1000);
  const int max_corners = req.params.get_int("max", 32, 0, 4096);
  const int dist = req.params.get_int("distance", 8, 0, 1000);
  req.params.check_all_used();
  auto resp = host_response(a.data, w, h, w);
  int32_t maxv = 0;
  for (int32_t v : resp) maxv = std::max(maxv, v);
  const int32_t thr = int32_t(int64_t(maxv) * permille / 1000);
  // The frame with a mark on each point: a dot per candidate (harris_nms), a cross per corner
  // taken (harris_select).
  auto mark = [](Image &out, int x, int y, int arm) {
    for (int d = -arm; d <= arm; ++d) {
      if (x + d >= 0 && x + d < out.width) out.at(x + d, y) = 255;
      if (y + d >= 0 && y + d < out.height) out.at(x, y + d) = 255;
    }
  };
  if (req.kernel == "harris_nms") {
    p.call = nms_call(w, h, w, std::move(resp), thr, "run");
    p.write = [a, mark](std::vector<std::vector<uint8_t>> &bufs, const std::string &path) {
      Image out = a;
      int32_t n;
      std::memcpy(&n, bufs[2].data(), 4);
      const int32_t *c = reinterpret_cast<const int32_t *>(bufs[1].data());
      for (int k = 0; k < n; ++k) mark(out, c[2 * k] & 0xFFFF, c[2 * k] >> 16, 0);
      write_image(path, out);
    };
    p.summary = size_name(w, h) + ", candidates above " + std::to_string(thr);
    return p;
  }
  p.call = select_call(host_nms(resp, w, h, w, thr), max_corners, dist, "run", double(w) * h);
  std::fill(p.call.bufs[1].data.begin(), p.call.bufs[1].data.end(), 0xFF);  // x = -1 ends the list
  p.write = [a, max_corners, mark](std::vector<std::vector<uint8_t>> &bufs, const std::string &path) {
    Image out = a;
    const int32_t *c = reinterpret_cast<const int32_t *>(bufs[1].data());
    for (int k = 0; k < max_corners; ++k) {
      if (c[3 * k] < 0) break;
      mark(out, c[3 * k], c[3 * k + 1], 3);
    }
    write_image(path, out);
  };
  p.summary = size_name(w, h) + ", corners above " + std::to_string(thr) +
              " marked with crosses";
  return p;
}

const Family kHarris{"harris", {"harris_response", "harris_nms", "harris_select"}, check, bench_call, lower_bound,
                     plan_run};
BVB_FAMILY(kHarris);

}  // namespace
}  // namespace bvb
