#include "pipe_common.h"

#include <algorithm>
#include <cmath>

#include "elf_symbols.h"
#include "scene/bench_scene.h"
#include "io.h"
#include "target.h"

namespace bvb {
namespace pipe {

bvb_pipe_frame frame_info(const FrameInput &in, int stages) {
  bvb_pipe_frame f{};
  f.index = in.index;
  // Cumulative counts wrap at 2^31 in the firmware's words; differences stay right.
  f.left_ticks = int32_t(uint32_t(uint64_t(in.truth.left_ticks)));
  f.right_ticks = int32_t(uint32_t(uint64_t(in.truth.right_ticks)));
  f.stages = stages;
  return f;
}

FrameOutput decode_result(const std::vector<uint8_t> &result, const std::vector<std::string> &diag_names) {
  const bvb_pipe_result r = from_bytes<bvb_pipe_result>(result);
  FrameOutput o;
  o.has_decision = true;
  switch (r.decision) {
    case BVB_PIPE_FORWARD: o.decision = Drive::Forward; break;
    case BVB_PIPE_LEFT: o.decision = Drive::Left; break;
    case BVB_PIPE_RIGHT: o.decision = Drive::Right; break;
    default: o.decision = Drive::Stop; break;
  }
  if (r.has_pose) {
    o.has_pose = true;
    o.x_in = r.x_q16 / 65536.0;
    o.y_in = r.y_q16 / 65536.0;
    o.heading_deg = r.heading_q16 / 65536.0;
  }
  for (size_t i = 0; i < diag_names.size() && i < BVB_PIPE_DIAG; ++i) o.diag.push_back({diag_names[i], r.diag[i]});
  return o;
}

Placer::Placer() {
  static const std::vector<uint64_t> room = [] {
    // Conservative defaults when the image cannot be read (host-only runs need no placement).
    std::vector<uint64_t> r(BVB_PLACE_COUNT, 0);
    r[BVB_PLACE_L1A] = 24 * 1024;
    r[BVB_PLACE_L1B] = 16 * 1024;
    r[BVB_PLACE_SCRATCH] = 3 * 1024;
    static const char *names[][2] = {{"", ""},
                                     {"_l1a_arena_start", "_l1a_arena_end"},
                                     {"_l1b_arena_start", "_l1b_arena_end"},
                                     {"_scratch_arena_start", "_scratch_arena_end"}};
    const std::string elf = product_firmware().elf;
    for (int p = BVB_PLACE_L1A; p <= BVB_PLACE_SCRATCH; ++p) {
      uint32_t lo = 0, hi = 0;
      if (symbol_value(elf, names[p][0], &lo) && symbol_value(elf, names[p][1], &hi) && hi > lo) r[p] = hi - lo;
    }
    return r;
  }();
  for (int p = 0; p < BVB_PLACE_COUNT; ++p) room_[p] = room[size_t(p)];
}

uint32_t Placer::place(const Buffer &b, std::initializer_list<uint32_t> prefer) {
  const uint64_t need = b.data.size() + 2 * b.guard + b.align + b.skew;
  for (uint32_t p : prefer)
    if (p != BVB_PLACE_SDRAM && p < BVB_PLACE_WINDOW && need <= room_[p]) {
      room_[p] -= need;
      return p;
    }
  return BVB_PLACE_SDRAM;
}

int horizon_row(const Camera &cam) {
  const double row = cam.cy - cam.fy * std::tan(deg2rad(cam.tilt_deg));
  return std::clamp(int(std::ceil(row)), 0, cam.height - 2);
}

std::vector<SceneFrame> render_frames(const std::string &spec, int count) {
  SceneGenerator gen(parse_scene_spec(spec));
  std::vector<SceneFrame> out;
  for (int f = 0; f < count; ++f) {
    out.push_back({gen.render().grey, gen.truth(), gen.camera()});
    if (f + 1 < count) gen.advance();
  }
  return out;
}

std::string bundled_scene_dir(const std::string &name) { return std::string(BVB_SOURCE_DIR) + "/frames/scenes/" + name; }

std::vector<SceneFrame> bundled_frames(const std::string &name, int first, int count) {
  const SceneData d = read_scene(bundled_scene_dir(name));
  std::vector<SceneFrame> out;
  for (int f = first; f < std::min(d.frames, first + count); ++f)
    out.push_back({d.grey(f), d.truth[size_t(f)], d.camera});
  return out;
}

std::vector<SceneFrame> bench_frames(int w, int h) {
  const BenchScene &b = bench_scene(w, h);
  std::vector<SceneFrame> out;
  for (size_t f = 0; f < b.grey.size(); ++f) out.push_back({b.grey[f], b.truth[f], b.camera});
  return out;
}

std::vector<CheckCall> host_sequence(const PipelineDef &def, const std::vector<SceneFrame> &frames,
                                     Params &params, int state_buffer, std::vector<FrameOutput> *outputs) {
  std::vector<CheckCall> calls;
  std::vector<uint8_t> state;
  for (size_t f = 0; f < frames.size(); ++f) {
    FrameInput in;
    in.index = int(f);
    in.grey = &frames[f].grey;
    in.truth = frames[f].truth;
    in.camera = &frames[f].camera;
    CheckCall cc = def.make_call(in, params);
    Buffer &sb = cc.bufs[size_t(state_buffer)];
    sb.persistent = false;
    if (f > 0) sb.data = state;
    std::vector<std::vector<uint8_t>> host;
    for (const auto &b : cc.bufs) host.push_back(b.data);
    HostBuffers hb(host);
    cc.host(hb);
    state = host[size_t(state_buffer)];
    if (outputs) outputs->push_back(def.decode(host));
    calls.push_back(std::move(cc));
  }
  return calls;
}

}  // namespace pipe
}  // namespace bvb
