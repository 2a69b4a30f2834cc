// Check, bench and run for bvb/region.h: region_grow (seeded region growing) and free_space
// (per-column obstacle boundary of a mask).
#include "bvb/region.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "family.h"
#include "io.h"
#include "patterns.h"
#include "robot_view.h"
#include "scene/bench_scene.h"
#include "formats.h"
#include "names.h"

namespace bvb {
namespace {

// Skews each buffer as its element type allows, then places them all together.
void place_buffers(Checker &ck, CheckCall &c, Rng &rng) {
  for (auto &b : c.bufs) {
    // Byte planes may start anywhere; int16/int32 data keeps its alignment.
    if (b.name == "img" || b.name == "mask") b.skew = uint32_t(rng.uniform(0, 3));
    if (b.name == "rows") b.skew = uint32_t(2 * rng.uniform(0, 1));
  }
  ck.place_randomly(c);
}

// ---- region_grow ----

CheckCall grow_call(std::vector<uint8_t> img, int w, int h, int is, int ms, bvb_region_params prm,
                    int queue_cap, const std::string &case_name) {
  CheckCall c;
  c.kernel = "region_grow";
  c.case_name = case_name;
  c.pixels = double(w) * h;
  int ii = c.in("img", std::move(img), View{1, false, w, h, is});
  int im = c.out("mask", size_t(ms) * (h - 1) + w, View{1, false, w, h, ms});
  int ip = c.in("params", bytes_of(prm), View{4, true});
  int iq = c.scratch("queue", size_t(std::max(queue_cap, 1)) * 4);
  int is_ = c.out("stats", sizeof(bvb_region_stats), View{4, true});
  c.buf(ii).word(is).buf(im).word(ms).word(w).word(h).buf(ip).buf(iq).word(queue_cap).buf(is_);
  c.host = [=](HostBuffers &m) {
    std::vector<int32_t> q(size_t(std::max(queue_cap, 1)));
    bvb_region_grow_c(m.u8(ii), is, m.u8(im), ms, w, h, m.as<bvb_region_params>(ip), q.data(), queue_cap,
                      m.as<bvb_region_stats>(is_));
  };
  return c;
}

// The robot's ground segmentation: seeded at the bottom middle, growing over the floor.
constexpr int kTol = 20;

void check_grow(Checker &ck) {
  Rng &rng = ck.rng();
  for (Size s : check_sizes(1, 1, rng, ck.options().campaign)) {
    for (Pattern pat : ck.patterns()) {
      const int is = pick_stride(s.w, rng), ms = pick_stride(s.w, rng);
      bvb_region_params prm;
      switch (rng.uniform(0, 5)) {
        case 0: prm.seed_x = s.w / 2, prm.seed_y = s.h - 1; break;
        case 1: prm.seed_x = rng.uniform(0, 1) * (s.w - 1), prm.seed_y = rng.uniform(0, 1) * (s.h - 1); break;
        case 2:  // outside the frame: an empty region
          prm.seed_x = rng.uniform(0, 1) ? -1 : s.w, prm.seed_y = rng.uniform(-1, s.h);
          break;
        default: prm.seed_x = rng.uniform(0, s.w - 1), prm.seed_y = rng.uniform(0, s.h - 1);
      }
      const int t = rng.uniform(0, 7);
      prm.tol = t == 0 ? 0 : t == 1 ? 255 : rng.uniform(1, 60);
      prm.connectivity = rng.uniform(0, 1) ? 8 : 4;
      const int full = s.w * s.h;
      const int r = rng.uniform(0, 4);
      const int cap = r == 0 ? rng.uniform(0, 3) : r == 1 ? rng.uniform(1, std::max(full / 8, 1)) : full;
      std::string name = size_name(s.w, s.h) + " strides " + std::to_string(is) +
                         "/" + std::to_string(ms) + " " + pattern_name(pat) + " seed " +
                         std::to_string(prm.seed_x) + "," + std::to_string(prm.seed_y) + " tol " +
                         std::to_string(prm.tol) + " conn " + std::to_string(prm.connectivity) + " queue " +
                         std::to_string(cap);
      CheckCall c = grow_call(make_plane(pat, s.w, s.h, is, rng, ck.options().frames_real), s.w, s.h, is, ms,
                              prm, cap, name);
      place_buffers(ck, c, rng);
      ck.add(std::move(c));
    }
  }
  for (Size s : std::vector<Size>{{160, 120}, {80, 60}, {161, 121}}) {
    for (int pose = 0; pose < 4; ++pose) {
      const Image &grey = robot_view(s.w, s.h, pose).grey;
      bvb_region_params prm{s.w / 2, s.h - 1, kTol, pose & 1 ? 8 : 4};
      const int cap = pose == 2 ? 2 * (s.w + s.h) : s.w * s.h;
      CheckCall c = grow_call(grey.data, s.w, s.h, s.w, s.w, prm, cap,
                              size_name(s.w, s.h) + " robot view " +
                                  std::to_string(pose) + " conn " + std::to_string(prm.connectivity) +
                                  " queue " + std::to_string(cap));
      place_buffers(ck, c, rng);
      ck.add(std::move(c));
    }
  }
}

// ---- free_space ----

CheckCall free_call(std::vector<uint8_t> mask, int w, int h, int ms, int min_gap, const std::string &case_name) {
  CheckCall c;
  c.kernel = "free_space";
  c.case_name = case_name;
  c.pixels = double(w) * h;
  int im = c.in("mask", std::move(mask), View{1, false, w, h, ms});
  int ir = c.out("rows", size_t(w) * 2, View{2, true, w, 1, w});
  c.buf(im).word(ms).word(w).word(h).word(min_gap).buf(ir);
  c.host = [=](HostBuffers &m) { bvb_free_space_c(m.u8(im), ms, w, h, min_gap, m.as<int16_t>(ir)); };
  return c;
}

// The floor mask of a grey frame, as the robot's pipeline makes it (host reference).
std::vector<uint8_t> floor_mask(const Image &grey, int tol, int conn) {
  const int w = grey.width, h = grey.height;
  std::vector<uint8_t> mask(size_t(w) * h);
  std::vector<int32_t> q(size_t(w) * h);
  bvb_region_params prm{w / 2, h - 1, tol, conn};
  bvb_region_stats st;
  bvb_region_grow_c(grey.data.data(), w, mask.data(), w, w, h, &prm, q.data(), w * h, &st);
  return mask;
}

void check_free(Checker &ck) {
  Rng &rng = ck.rng();
  for (Size s : check_sizes(1, 1, rng, ck.options().campaign)) {
    for (Pattern pat : ck.patterns()) {
      const int ms = pick_stride(s.w, rng);
      auto mask = make_plane(pat, s.w, s.h, ms, rng, ck.options().frames_real);
      // Thresholded, the patterns make long runs of floor and obstacle; raw, any non-zero byte
      // is floor (Noise and Runs keep their zeros).
      const bool threshold = rng.uniform(0, 2) != 0;
      if (threshold)
        for (int y = 0; y < s.h; ++y)
          for (int x = 0; x < s.w; ++x) {
            uint8_t &v = mask[size_t(y) * ms + x];
            v = v >= 128 ? 255 : 0;
          }
      const int g = rng.uniform(0, 5);
      const int min_gap = g == 0 ? 1 : g == 1 ? s.h + rng.uniform(0, 3) : rng.uniform(1, 6);
      std::string name = size_name(s.w, s.h) + " stride " + std::to_string(ms) +
                         " " + pattern_name(pat) + (threshold ? " >=128" : " raw") + " min_gap " +
                         std::to_string(min_gap);
      CheckCall c = free_call(std::move(mask), s.w, s.h, ms, min_gap, name);
      place_buffers(ck, c, rng);
      ck.add(std::move(c));
    }
  }
  for (int pose = 0; pose < 4; ++pose) {
    const Image &grey = robot_view(160, 120, pose).grey;
    for (int min_gap : {1, 3}) {
      CheckCall c = free_call(floor_mask(grey, kTol, 4), 160, 120, 160, min_gap,
                              "160x120 floor of robot view " + std::to_string(pose) + " min_gap " +
                                  std::to_string(min_gap));
      place_buffers(ck, c, rng);
      ck.add(std::move(c));
    }
  }
}

void check(Checker &ck) {
  check_grow(ck);
  check_free(ck);
}

CheckCall bench_call(const std::string &kernel, int w, int h, Rng &) {
  const Image &grey = bench_scene(w, h).grey[0];  // hermetic: scene/bench_scene.h
  const std::string name = size_name(w, h);
  if (kernel == "free_space") return free_call(floor_mask(grey, kTol, 4), w, h, w, 3, name);
  bvb_region_params prm{w / 2, h - 1, kTol, 4};
  return grow_call(grey.data, w, h, w, w, prm, w * h, name);
}

// Lower bounds of the bench calls, from what the bench frame makes the kernels do.
// region_grow: per grown pixel (each is taken from the queue once) at least 20 issues: four
// neighbour byte tests (compare + branch each), the tolerance test (multiply, subtract, abs,
// compare, branch), count / sum / tol * count / bounding box / sum_x,sum_y updates, the queue
// bookkeeping and the loop branch, with every load and store in a parallel slot and no branch
// penalties counted.
// free_space: the assembly's method, 9 single-issue ALU ops per two pixels (4.5 per pixel), over
// the rows it must scan: in each strip of columns (64 wide in frames wider than 320, else the
// whole row) from the bottom up to the row where the strip's last column is decided.
double lower_bound(const std::string &kernel, int w, int h) {
  const Image &grey = bench_scene(w, h).grey[0];  // hermetic: scene/bench_scene.h
  if (kernel == "free_space") {
    const std::vector<uint8_t> mask = floor_mask(grey, kTol, 4);
    const int min_gap = 3, strip = w > 320 ? 64 : w;
    double ops = 0;
    for (int x0 = 0; x0 < w; x0 += strip) {
      const int x1 = std::min(w, x0 + strip);
      int top = h;  // lowest row index scanned in this strip
      for (int x = x0; x < x1; ++x) {
        int gap = 0, y = h - 1;
        for (; y >= 0; --y) {
          if (mask[size_t(y) * w + x]) {
            gap = 0;
            continue;
          }
          if (++gap >= min_gap || y == 0) break;
        }
        top = std::min(top, std::max(y, 0));
      }
      ops += 4.5 * (x1 - x0) * (h - top);
    }
    return ops;
  }
  std::vector<uint8_t> mask(size_t(w) * h);
  std::vector<int32_t> q(size_t(w) * h);
  bvb_region_params prm{w / 2, h - 1, kTol, 4};
  bvb_region_stats st;
  bvb_region_grow_c(grey.data.data(), w, mask.data(), w, w, h, &prm, q.data(), w * h, &st);
  return 20.0 * st.count;
}

// width * height * max(width, height) < 2^31: the kernel's sums stay in an int32.
void check_frame_limit(const std::string &kernel, int w, int h) {
  if (double(w) * h * std::max(w, h) >= 2147483648.0)
    throw InputError(kernel + ": frame too large (width * height * max(width, height) must stay below 2^31)");
}

RunPlan plan_grow(RunRequest &req) {
  if (req.inputs.size() != 1) throw InputError("region_grow takes one --in frame");
  Image img = read_input(req, 0);
  const int w = img.width, h = img.height;
  check_frame_limit("region_grow", w, h);
  bvb_region_params prm;
  prm.seed_x = req.params.get_int("seed_x", w / 2, -1, w);
  prm.seed_y = req.params.get_int("seed_y", h - 1, -1, h);
  prm.tol = req.params.get_int("tol", kTol, 0, 255);
  prm.connectivity = req.params.get_int("conn", 4, 4, 8);
  if (prm.connectivity != 4 && prm.connectivity != 8) throw InputError("region_grow: conn must be 4 or 8");
  const int cap = req.params.get_int("queue", w * h, 0, w * h);
  req.params.check_all_used();
  RunPlan p;
  p.call = grow_call(img.data, w, h, w, w, prm, cap, "run");
  p.write = [w, h](std::vector<std::vector<uint8_t>> &bufs, const std::string &path) {
    Image out(w, h);
    out.data = bufs[1];
    write_image(path, out);
    bvb_region_stats st;
    std::memcpy(&st, bufs[4].data(), sizeof st);
    std::printf("region: %d pixels, mean %.1f, box (%d,%d)-(%d,%d), centroid (%.1f, %.1f), dropped %d\n", st.count,
                st.count ? double(st.sum) / st.count : 0.0, st.min_x, st.min_y, st.max_x, st.max_y,
                st.count ? double(st.sum_x) / st.count : 0.0, st.count ? double(st.sum_y) / st.count : 0.0,
                st.dropped);
  };
  p.summary = size_name(w, h) + " seed " + std::to_string(prm.seed_x) + "," +
              std::to_string(prm.seed_y) + " tol " + std::to_string(prm.tol);
  return p;
}

// Input: a mask frame (non-zero = floor). Output: CSV column,boundary_row.
RunPlan plan_free(RunRequest &req) {
  if (req.inputs.size() != 1) throw InputError("free_space takes one --in mask frame");
  Image img = read_input(req, 0);
  const int w = img.width, h = img.height;
  const int min_gap = req.params.get_int("min_gap", 1, 1, 4096);
  req.params.check_all_used();
  RunPlan p;
  p.call = free_call(img.data, w, h, w, min_gap, "run");
  p.write = [w](std::vector<std::vector<uint8_t>> &bufs, const std::string &path) {
    std::string csv = "column,boundary_row\n";
    for (int x = 0; x < w; ++x) {
      int16_t r;
      std::memcpy(&r, bufs[1].data() + 2 * x, 2);
      csv += std::to_string(x) + "," + std::to_string(r) + "\n";
    }
    write_text_output(path, csv);
  };
  p.kind = OutputKind::Text;
  p.summary = size_name(w, h) + " min_gap " + std::to_string(min_gap);
  return p;
}

RunPlan plan_run(RunRequest &req) { return req.kernel == "free_space" ? plan_free(req) : plan_grow(req); }

const Family kRegion{"region", {"region_grow", "free_space"}, check, bench_call, lower_bound, plan_run};
BVB_FAMILY(kRegion);

}  // namespace
}  // namespace bvb
