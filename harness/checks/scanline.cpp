// Check, bench and run for bvb/scanline.h (scan-line profiles and their shift).
#include "bvb/scanline.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "family.h"
#include "io.h"
#include "patterns.h"
#include "formats.h"
#include "names.h"

namespace bvb {
namespace {

// Inputs at any alignment, words where the header says so; then one memory when they fit, or
// for the profile half the calls as the robot runs it (the band in SDRAM, the scratch in L1:
// the row-band stream, firmware/asm/scanline.S).
void place_buffers(Checker &ck, CheckCall &c, Rng &rng, bool skew_all_inputs, int streaming_scratch = -1) {
  for (auto &b : c.bufs)
    if (b.role == Role::In || (skew_all_inputs && b.role == Role::Out && b.view.elem == 1))
      b.skew = uint32_t(rng.uniform(0, 3));
  if (streaming_scratch >= 0)
    ck.place_streaming(c, size_t(streaming_scratch), rng);
  else
    ck.place_randomly(c);
}

CheckCall profile_call(int w, int rows, int stride, std::vector<uint8_t> band, const std::string &case_name) {
  CheckCall c;
  c.kernel = "scanline_profile_u8";
  c.case_name = case_name;
  c.pixels = double(w) * rows;
  const View sv{1, false, w, rows, stride}, pv{1, false, w, 1, w};
  int is = c.in("band", std::move(band), sv);
  int ip = c.out("profile", size_t(w), pv);
  int iscr = c.scratch("scratch", BVB_SCANLINE_PROFILE_SCRATCH_BYTES(w));
  c.buf(is).word(w).word(rows).word(stride).buf(ip).buf(iscr);
  c.host = [=](HostBuffers &m) { bvb_scanline_profile_u8_c(m.u8(is), w, rows, stride, m.u8(ip), m.u8(iscr)); };
  return c;
}

// Work of a shift search: the absolute differences summed over every shift.
double shift_terms(int w, int rho) {
  double n = w;
  for (int k = 1; k <= w - rho; ++k) n += 2.0 * (w - k);
  return n;
}

CheckCall shift_call(std::vector<uint8_t> p1, std::vector<uint8_t> p2, int w, int rho, bool with_curve,
                     const std::string &case_name) {
  CheckCall c;
  c.kernel = "scanline_shift_u8";
  c.case_name = case_name;
  c.pixels = shift_terms(w, rho);
  const int T = w - rho;
  int i1 = c.in("p1", std::move(p1), View{1, false, w, 1, w});
  int i2 = c.in("p2", std::move(p2), View{1, false, w, 1, w});
  int ir = c.out("result", 12, View{4, true, 3, 1, 3});
  c.buf(i1).buf(i2).word(w).word(rho).buf(ir);
  int ic = -1;
  if (with_curve) {
    ic = c.out("curve", size_t(2 * T + 1) * 4, View{4, false, 2 * T + 1, 1, 2 * T + 1});
    c.buf(ic);
  } else {
    c.word(0);
  }
  c.host = [=](HostBuffers &m) {
    bvb_scanline_shift_u8_c(m.u8(i1), m.u8(i2), w, rho, m.s32(ir), ic >= 0 ? m.u32(ic) : nullptr);
  };
  return c;
}

// A profile-like byte sequence: a pattern's row, or a real frame's column means.
std::vector<uint8_t> profile_bytes(Pattern p, int w, Rng &rng, const std::string &frames_real) {
  if (p == Pattern::Real) {
    Image img = real_crop(frames_real, w, 24, rng);
    if (!img.data.empty()) {
      std::vector<uint8_t> prof(w);
      for (int x = 0; x < w; ++x) {
        int s = 0;
        for (int y = 0; y < 24; ++y) s += img.at(x, y);
        prof[x] = uint8_t((s + 12) / 24);
      }
      return prof;
    }
  }
  return make_plane(p, w, 1, w, rng, frames_real);
}

void check_profile(Checker &ck) {
  Rng &rng = ck.rng();
  std::vector<Size> sizes = check_sizes(1, 1, rng, ck.options().campaign);
  // Widths 1..17 meet every phase of the 8-column loop; rows 1..3 and up to the 256 limit.
  for (int w = 1; w <= 17; ++w) sizes.push_back({w, w % 5 + 1});
  for (int rows : {128, 255, 256}) sizes.push_back({rng.uniform(1, 70), rows});
  for (Size s : sizes) {
    const int rows = std::min(s.h, BVB_SCANLINE_MAX_ROWS);
    for (Pattern p : ck.patterns()) {
      const int ss = pick_stride(s.w, rng);
      std::string name = std::to_string(s.w) + " x " + std::to_string(rows) + " rows stride " +
                         std::to_string(ss) + " " + pattern_name(p);
      CheckCall c = profile_call(s.w, rows, ss, make_plane(p, s.w, rows, ss, rng, ck.options().frames_real), name);
      place_buffers(ck, c, rng, true, 2);
      ck.add(std::move(c));
    }
  }
}

void check_shift(Checker &ck) {
  Rng &rng = ck.rng();
  struct Case {
    int w, rho;
  };
  std::vector<Case> cases = {{1, 1}, {2, 1}, {2, 2}, {5, 1}, {8, 3}, {9, 9}, {16, 4}, {88, 40}, {160, 80}};
  for (int i = 0; i < (ck.options().campaign ? 24 : 8); ++i) {
    const int w = rng.uniform(1, ck.options().campaign ? BVB_SCANLINE_MAX_WINDOW : 320);
    cases.push_back({w, rng.uniform(1, w)});
  }
  if (ck.options().campaign) cases.push_back({BVB_SCANLINE_MAX_WINDOW, 1000});
  for (const Case &k : cases) {
    for (Pattern p : ck.patterns()) {
      std::vector<uint8_t> p1 = profile_bytes(p, k.w, rng, ck.options().frames_real), p2(k.w);
      // p2: p1 moved by a known shift with a little noise, or an unrelated profile.
      const int T = k.w - k.rho, d = rng.uniform(-T, T), mode = rng.uniform(0, 3);
      for (int x = 0; x < k.w; ++x) {
        const int src = std::clamp(x - d, 0, k.w - 1);
        int v = p1[src] + (mode == 1 ? rng.uniform(-3, 3) : 0);
        if (mode == 3) v = int(rng.u32() & 255);
        p2[x] = uint8_t(std::clamp(v, 0, 255));
      }
      const bool curve = rng.uniform(0, 3) != 0;
      std::string name = "w " + std::to_string(k.w) + " rho " + std::to_string(k.rho) + " " + pattern_name(p) +
                         (mode == 3 ? " unrelated" : " moved " + std::to_string(d)) + (curve ? " +curve" : "");
      CheckCall c = shift_call(std::move(p1), std::move(p2), k.w, k.rho, curve, name);
      place_buffers(ck, c, rng, false);
      ck.add(std::move(c));
    }
  }
  // Extremes: every lane of SAA at its largest sum (0 against 255 over the longest overlap).
  for (int w : {BVB_SCANLINE_MAX_WINDOW, 1023, 513}) {
    std::vector<uint8_t> z(w, 0), f(w, 255);
    ck.add(shift_call(z, f, w, w - 3, true, "w " + std::to_string(w) + " zeros against 255s"));
    ck.add(shift_call(f, z, w, 1, false, "w " + std::to_string(w) + " 255s against zeros"));
  }
}

void check(Checker &ck) {
  check_profile(ck);
  check_shift(ck);
}

CheckCall bench_call(const std::string &kernel, int w, int h, Rng &rng) {
  const std::string name = size_name(w, h);
  if (kernel == "scanline_profile_u8") {
    const int rows = std::min(h / 2, BVB_SCANLINE_MAX_ROWS);
    CheckCall c = profile_call(w, rows, w, make_plane(Pattern::Noise, w, rows, w, rng, ""), name);
    c.bufs[2].place = BVB_PLACE_L1B;  // the band in SDRAM, the sums and band buffers in L1
    return c;
  }
  // The whole image width as the window, half of it as the minimum overlap; p2 is p1 moved
  // by a few pixels with noise, as between two frames of a turning robot.
  const int win = std::min(w, BVB_SCANLINE_MAX_WINDOW);
  std::vector<uint8_t> p1 = make_plane(Pattern::Noise, win, 1, win, rng, ""), p2(win);
  for (int x = 0; x < win; ++x) p2[x] = uint8_t(std::clamp(p1[std::max(x - 7, 0)] + rng.uniform(-4, 4), 0, 255));
  return shift_call(p1, p2, win, win / 2, true, name);
}

// Profile: BYTEOP16P and two adds per 8 pixels, 5 ops per 2 columns to normalise.
// Shift: SAA's four absolute differences per cycle.
double lower_bound(const std::string &kernel, int w, int h) {
  if (kernel == "scanline_profile_u8") {
    const int rows = std::min(h / 2, BVB_SCANLINE_MAX_ROWS);
    // The bus, 1 byte in per pixel at 0.5 byte per core cycle (bvb/dma.h), above the sum pass's
    // 0.375; then the normalising pass once the last row is in.
    return 2.0 * w * rows + 2.5 * w;
  }
  const int win = std::min(w, BVB_SCANLINE_MAX_WINDOW);
  return shift_terms(win, win / 2) / 4;
}

std::vector<uint8_t> host_profile(const Image &img, int y0, int rows) {
  std::vector<uint8_t> prof(img.width);
  bvb_scanline_profile_u8_c(&img.data[size_t(y0) * img.width], img.width, rows, img.width, prof.data(), nullptr);
  return prof;
}

RunPlan plan_run(RunRequest &req) {
  const bool profile = req.kernel == "scanline_profile_u8";
  if (req.inputs.size() != (profile ? 1u : 2u))
    throw InputError(req.kernel + (profile ? " takes one --in frame" : " takes two --in frames"));
  Image a = read_input(req, 0);
  const int rows = req.params.get_int("rows", std::min(std::max(a.height / 2, 1), BVB_SCANLINE_MAX_ROWS), 1,
                                      std::min(a.height, BVB_SCANLINE_MAX_ROWS));
  const int y0 = req.params.get_int("y0", (a.height - rows) / 2, 0, a.height - rows);
  RunPlan p;
  if (profile) {
    req.params.check_all_used();
    std::vector<uint8_t> band(a.data.begin() + size_t(y0) * a.width, a.data.begin() + size_t(y0 + rows) * a.width);
    p.call = profile_call(a.width, rows, a.width, band, "run");
    p.write = [](std::vector<std::vector<uint8_t>> &bufs, const std::string &path) {
      std::string out = "x,profile\n";
      for (size_t x = 0; x < bufs[1].size(); ++x) out += std::to_string(x) + "," + std::to_string(bufs[1][x]) + "\n";
      write_text_output(path, out);
    };
    p.kind = OutputKind::Text;
    p.summary = std::to_string(a.width) + " columns, rows " + std::to_string(y0) + ".." + std::to_string(y0 + rows - 1);
    return p;
  }
  Image b = read_input(req, 1);
  if (a.width != b.width || a.height != b.height) throw InputError(req.kernel + ": the two frames differ in size");
  const int w = req.params.get_int("w", std::min(a.width, BVB_SCANLINE_MAX_WINDOW), 1,
                                   std::min(a.width, BVB_SCANLINE_MAX_WINDOW));
  const int x0 = req.params.get_int("x0", (a.width - w) / 2, 0, a.width - w);
  const int rho = req.params.get_int("rho", std::max(w / 2, 1), 1, w);
  req.params.check_all_used();
  // The profiles come from the host reference; the call is the shift search.
  std::vector<uint8_t> pa = host_profile(a, y0, rows), pb = host_profile(b, y0, rows);
  p.call = shift_call(std::vector<uint8_t>(pa.begin() + x0, pa.begin() + x0 + w),
                      std::vector<uint8_t>(pb.begin() + x0, pb.begin() + x0 + w), w, rho, true, "run");
  const int T = w - rho;
  p.write = [w, T](std::vector<std::vector<uint8_t>> &bufs, const std::string &path) {
    int32_t res[3];
    std::memcpy(res, bufs[2].data(), sizeof res);
    std::string out = "# best shift " + std::to_string(res[0]) + ", S " + std::to_string(res[1]) + ", overlap " +
                      std::to_string(res[2]) + "\nt,S,overlap,f\n";
    for (int t = -T; t <= T; ++t) {
      uint32_t s;
      std::memcpy(&s, bufs[3].data() + size_t(t + T) * 4, 4);
      const int n = w - (t < 0 ? -t : t);
      char f[32];
      std::snprintf(f, sizeof f, "%.4f", double(s) / n);
      out += std::to_string(t) + "," + std::to_string(s) + "," + std::to_string(n) + "," + f + "\n";
    }
    write_text_output(path, out);
  };
  p.kind = OutputKind::Text;
  p.summary = "window " + std::to_string(w) + " at x " + std::to_string(x0) + ", rho " + std::to_string(rho) +
              ", rows " + std::to_string(y0) + ".." + std::to_string(y0 + rows - 1);
  return p;
}

const Family kScanline{"scanline", {"scanline_profile_u8", "scanline_shift_u8"}, check, bench_call, lower_bound,
                       plan_run};
BVB_FAMILY(kScanline);

}  // namespace
}  // namespace bvb
