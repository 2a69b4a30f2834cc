// bfbench pipeline seg_avoid: segmentation-based obstacle avoidance (bvb/pipeline.h), and its
// kernel family (host C = Blackfin C = assembly build on bundled scenes; bench on a rendered
// frame).
#include <algorithm>

#include "pipe_common.h"
#include "names.h"

namespace bvb {
namespace {

const std::vector<std::string> kDiag = {"stages",    "ahead_px",    "left_free", "right_free",
                                        "region_px", "region_mean", "ground_q8", "flags"};
enum { kFrame, kInfo, kParams, kState, kResult, kMask, kMap, kWork };

// Defaults, for 160x120 (rows scale with the height, columns with the width).
bvb_seg_avoid_params params_for(const FrameInput &in, Params &prm) {
  const int w = in.grey->width, h = in.grey->height;
  const Camera cam = in.camera ? *in.camera : Camera::standard(w, h);
  bvb_seg_avoid_params p{};
  p.tol = prm.get_int("tol", 30, 0, 255);
  p.seed_search = prm.get_int("seed_search", w / 2, 0, w);
  p.horizon = prm.get_int("horizon", pipe::horizon_row(cam), 0, h - 2);
  p.change_tol = prm.get_int("change_tol", 12, 0, 255);
  p.min_region = prm.get_int("min_region", w * h / 40, 0, w * h);
  p.lost_frames = prm.get_int("lost_frames", 30, 1, 1000000);
  p.avg_shift = prm.get_int("avg_shift", 3, 0, 8);
  p.min_gap = prm.get_int("min_gap", std::max(1, 10 * h / 120), 1, h);
  p.go_rows = prm.get_int("go_rows", 30 * h / 120, 0, h);
  p.centre_lo = prm.get_int("centre_lo", w / 5, 1, w / 2);
  p.centre_hi = prm.get_int("centre_hi", w - w / 5, w / 2, w - 1);
  p.queue_cap = prm.get_int("queue_cap", 2 * (w + h), 1, w * h);
  p.light_jump_q8 = prm.get_int("light_jump_q8", 32, 0, 256);
  p.stall_q8 = prm.get_int("stall_q8", 0, 0, 256);
  p.stall_frames = prm.get_int("stall_frames", 3, 1, 1000000);
  p.stall_turn = prm.get_int("stall_turn", 30, 1, 1000000);
  return p;
}

CheckCall seg_call(const FrameInput &in, Params &prm) {
  const Image &g = *in.grey;
  const int w = g.width, h = g.height;
  const bvb_seg_avoid_params p = params_for(in, prm);
  const bvb_pipe_frame info = pipe::frame_info(in, prm.get_int("stages", 0, 0, BVB_SEG_AVOID_STAGES));
  const int rows = h - p.horizon;
  CheckCall c;
  c.kernel = "pipe_seg_avoid";
  c.case_name = "frame " + std::to_string(in.index);
  c.pixels = double(w) * h;
  c.in("frame", g.data, View{1, false, w, h, w});
  c.in("info", pipe::bytes_of(info), View{4, true});
  c.in("params", pipe::bytes_of(p), View{4, true});
  c.inout("state", std::vector<uint8_t>(BVB_SEG_AVOID_STATE_BYTES, 0), View{4, true});
  c.bufs[kState].persistent = true;
  c.out("result", sizeof(bvb_pipe_result), View{4, true});
  c.scratch("mask", size_t(w) * rows);
  c.scratch("map", size_t(w) * rows);
  c.scratch("work", size_t(BVB_SEG_AVOID_WORK_BYTES(w, p.queue_cap)));
  // The frame arrives in SDRAM; the working maps and the queue go to L1 when they fit.
  pipe::Placer pl;
  c.bufs[kWork].place = pl.place(c.bufs[kWork], {BVB_PLACE_SCRATCH, BVB_PLACE_L1B, BVB_PLACE_L1A});
  c.bufs[kMask].place = pl.place(c.bufs[kMask], {BVB_PLACE_L1A, BVB_PLACE_L1B});
  c.bufs[kMap].place = pl.place(c.bufs[kMap], {BVB_PLACE_L1B, BVB_PLACE_L1A});
  c.buf(kFrame).word(w).word(h).word(w).buf(kInfo).buf(kParams).buf(kState).buf(kResult);
  c.buf(kMask).buf(kMap).buf(kWork);
  c.host = [=](HostBuffers &m) {
    bvb_pipe_seg_avoid_c(m.u8(kFrame), w, h, w, m.as<bvb_pipe_frame>(kInfo), m.as<bvb_seg_avoid_params>(kParams),
                         m.as<bvb_seg_avoid_state>(kState), m.as<bvb_pipe_result>(kResult), m.u8(kMask),
                         m.u8(kMap), m.u8(kWork));
  };
  return c;
}

FrameOutput seg_decode(const std::vector<std::vector<uint8_t>> &bufs) {
  return pipe::decode_result(bufs[kResult], kDiag);
}

std::vector<std::string> seg_summary(const std::vector<FrameRecord> &frames) {
  int changes = 0, moved = 0, dropped = 0;
  std::string first;
  for (const auto &r : frames) {
    if (r.out.diag.size() < kDiag.size()) continue;
    const int flags = int(r.out.diag[7].second);
    if (flags & BVB_SEG_FLAG_CHANGE) {
      if (!changes) first = " (first in frame " + std::to_string(r.in.index) + ")";
      ++changes;
    }
    moved += (flags & BVB_SEG_FLAG_SEED_MOVED) != 0;
    dropped += (flags & BVB_SEG_FLAG_DROPPED) != 0;
  }
  return {"sudden ground changes: " + std::to_string(changes) + first + "; seed moved in " +
              std::to_string(moved) + " frames",
          "region queue overflowed in " + std::to_string(dropped) + " frames"};
}

const PipelineDef kSegAvoid{"seg_avoid",
                            "segmentation-based obstacle avoidance (region growing, 30-pixel rule)",
                            "pipe_seg_avoid",
                            seg_call,
                            seg_decode,
                            seg_summary};
BVB_PIPELINE(kSegAvoid);

// ---- the kernel family: the pipeline entry as one kernel ----

void check(Checker &ck) {
  // Short stretches of every bundled scene, each frame starting from the host build's state
  // after the previous one: the approach to the box (blocked at the end), the turn, the mover
  // with the lighting step at frame 16.
  struct Stretch {
    const char *scene;
    int first, count;
  };
  const Stretch stretches[] = {{"boxes_approach", 14, 8}, {"boxes_turn", 0, 5}, {"cylinders_mover", 13, 6}};
  for (const Stretch &s : stretches) {
    Params prm;
    auto frames = pipe::bundled_frames(s.scene, s.first, s.count);
    auto calls = pipe::host_sequence(kSegAvoid, frames, prm, kState);
    for (size_t i = 0; i < calls.size(); ++i) {
      calls[i].case_name = std::string(s.scene) + " frame " + std::to_string(s.first + int(i));
      ck.add(std::move(calls[i]));
    }
  }
  // Odd sizes are not what the robot's camera gives, but nothing in the orchestration may
  // depend on even ones: three generated 97x61 frames.
  Params prm;
  auto frames = pipe::render_frames("arena=cylinders,path=straight,size=97x61,frames=3,noise=2,uyvy=0,flow=0", 3);
  auto calls = pipe::host_sequence(kSegAvoid, frames, prm, kState);
  for (size_t i = 0; i < calls.size(); ++i) {
    calls[i].case_name = "cylinders 97x61 frame " + std::to_string(i);
    ck.add(std::move(calls[i]));
  }
}

CheckCall bench_call(const std::string &, int w, int h, Rng &) {
  if (!((w == 160 && h == 120) || (w == 320 && h == 240))) return {};
  // The bench scene (frames/scenes/bench_boxes_WxH): the boxes arena's start, looking at the red
  // box, then half an inch on; the call is the second frame's, from the state the
  // first leaves.
  Params prm;
  auto calls = pipe::host_sequence(kSegAvoid, pipe::bench_frames(w, h), prm, kState);
  CheckCall c = std::move(calls[1]);
  c.case_name = size_name(w, h);
  return c;
}

const Family kSegAvoidFamily{"pipe_seg_avoid", {"pipe_seg_avoid"}, check, bench_call, nullptr, nullptr};
BVB_FAMILY(kSegAvoidFamily);

}  // namespace
}  // namespace bvb
