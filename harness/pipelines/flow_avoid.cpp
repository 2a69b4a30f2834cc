// bfbench pipeline flow_avoid: optical-flow obstacle avoidance (bvb/pipeline.h), and its kernel
// family (host C = Blackfin C = assembly build on bundled scenes; bench on a rendered frame pair).
#include <algorithm>
#include <cmath>

#include "io.h"
#include "pipe_common.h"
#include "names.h"

namespace bvb {
namespace {

const std::vector<std::string> kDiag = {"stages", "flow_left_q9", "flow_right_q9", "mode",
                                        "d_left", "d_right",      "latch", "expansion_q9"};
enum { kFrame, kInfo, kParams, kState, kResult, kCoef, kFlowA, kFlowB };

// The image row where the floor is `dist_in` ahead of the camera (camera.h): the band stops
// there, so that the floor in it is farther away than that and moves little.
int far_floor_row(const Camera &cam, double dist_in) {
  const double below_axis = std::atan2(cam.cam_height_in, dist_in) - deg2rad(cam.tilt_deg);
  return std::clamp(int(std::lround(cam.cy + cam.fy * std::tan(below_axis))), 2, cam.height);
}

// Defaults, for 160x120: rows scale with the height; the threshold, a flow in pixels, with the
// width (flow in pixels grows with the resolution).
bvb_flow_avoid_params params_for(const FrameInput &in, Params &prm) {
  const int w = in.grey->width, h = in.grey->height;
  const Camera cam = in.camera ? *in.camera : Camera::standard(w, h);
  bvb_flow_avoid_params p{};
  p.alpha2_q4 = prm.get_int("alpha2_q4", 16 * 8 * 8, BVB_HS_ALPHA2_Q4_MIN, BVB_HS_ALPHA2_Q4_MAX);
  p.iterations = prm.get_int("iterations", 10, 0, 1000);
  // The flow is computed on a band about 40 pixels wide whatever the camera's resolution: at the
  // robot's 0.5 in per frame, near obstacles move farther per frame than Horn-Schunck without
  // a pyramid can follow at full resolution.
  int def_scale = 1;
  while (def_scale < 8 && w / (2 * def_scale) >= 40) def_scale *= 2;
  p.scale = prm.get_int("scale", def_scale, 1, 8);
  if (p.scale & (p.scale - 1)) throw InputError("flow_avoid: scale must be 1, 2, 4 or 8");
  p.band_top = prm.get_int("band_top", 0, 0, h - 2);
  const int far = far_floor_row(cam, 20.0) - p.band_top;
  p.band_rows = prm.get_int("band_rows", std::min(h - p.band_top, (far + p.scale - 1) / p.scale * p.scale), 2,
                            h - p.band_top);
  if (p.band_rows / p.scale < 2 || w / p.scale < 2) throw InputError("flow_avoid: the scaled band is smaller than 2x2");
  p.thresh_q9 = prm.get_int("thresh_q9", 80, 0, BVB_FLOW_AVOID_MAX_MAG);
  p.stall_q9 = prm.get_int("stall_q9", p.thresh_q9 / 16, 0, BVB_FLOW_AVOID_MAX_MAG);
  p.turn_frames = prm.get_int("turn_frames", 10, 1, 1000);
  p.stall_turn_frames = prm.get_int("stall_turn_frames", 40, 1, 1000);
  p.rot_ticks = prm.get_int("rot_ticks", 2, 0, 1000000);
  p.light_tol = prm.get_int("light_tol", 8, 0, 255);
  p.black = prm.get_int("black", 16, 0, 254);
  p.light_gain = prm.get_int("light_gain", 1, 0, 1);
  return p;
}

CheckCall flow_call(const FrameInput &in, Params &prm) {
  const Image &g = *in.grey;
  const int w = g.width, h = g.height;
  const bvb_flow_avoid_params p = params_for(in, prm);
  const bvb_pipe_frame info = pipe::frame_info(in, prm.get_int("stages", 0, 0, BVB_FLOW_AVOID_STAGES));
  const int rows = p.band_rows, s = p.scale;
  CheckCall c;
  c.kernel = "pipe_flow_avoid";
  c.case_name = "frame " + std::to_string(in.index);
  c.pixels = double(w) * h;
  c.in("frame", g.data, View{1, false, w, h, w});
  c.in("info", pipe::bytes_of(info), View{4, true});
  c.in("params", pipe::bytes_of(p), View{4, true});
  c.inout("state", std::vector<uint8_t>(size_t(BVB_FLOW_AVOID_STATE_BYTES(w, rows, s)), 0), View{4, true});
  c.bufs[kState].persistent = true;
  c.out("result", sizeof(bvb_pipe_result), View{4, true});
  // Coefficients and flow fields take 6 + 4 + 4 bytes per pixel of the scaled band (9 KB at
  // 160x120 with s = 4): the frame arrives in SDRAM, these go to L1 when they fit, as firmware
  // on the robot would place them (at s = 1 they are frame-sized and stay in SDRAM). The
  // coefficients and the flow fields in different banks: hs_iterate reads both every pixel.
  c.scratch("coef", size_t(BVB_FLOW_AVOID_COEF_BYTES(w, rows, s)));
  c.scratch("flow_a", size_t(BVB_FLOW_AVOID_FLOW_BYTES(w, rows, s)));
  c.scratch("flow_b", size_t(BVB_FLOW_AVOID_FLOW_BYTES(w, rows, s)));
  pipe::Placer pl;
  c.bufs[kCoef].place = pl.place(c.bufs[kCoef], {BVB_PLACE_L1A, BVB_PLACE_L1B});
  c.bufs[kFlowA].place = pl.place(c.bufs[kFlowA], {BVB_PLACE_L1B, BVB_PLACE_L1A});
  c.bufs[kFlowB].place = pl.place(c.bufs[kFlowB], {BVB_PLACE_L1B, BVB_PLACE_L1A});
  c.bufs[kState].place = pl.place(c.bufs[kState], {BVB_PLACE_L1A, BVB_PLACE_L1B});
  c.buf(kFrame).word(w).word(h).word(w).buf(kInfo).buf(kParams).buf(kState).buf(kResult);
  c.buf(kCoef).buf(kFlowA).buf(kFlowB);
  c.host = [=](HostBuffers &m) {
    bvb_pipe_flow_avoid_c(m.u8(kFrame), w, h, w, m.as<bvb_pipe_frame>(kInfo), m.as<bvb_flow_avoid_params>(kParams),
                          m.as<bvb_flow_avoid_state>(kState), m.as<bvb_pipe_result>(kResult), m.s16(kCoef),
                          m.s16(kFlowA), m.s16(kFlowB));
  };
  return c;
}

FrameOutput flow_decode(const std::vector<std::vector<uint8_t>> &bufs) {
  return pipe::decode_result(bufs[kResult], kDiag);
}

std::vector<std::string> flow_summary(const std::vector<FrameRecord> &frames) {
  int modes[5] = {0, 0, 0, 0, 0};
  double flow_cycles = 0;
  uint32_t flow_max = 0;
  for (const auto &r : frames) {
    if (r.out.diag.size() < kDiag.size()) continue;
    const int m = int(r.out.diag[BVB_FLOW_DIAG_MODE].second);
    if (m < 0 || m > 4) continue;
    ++modes[m];
    if (m == BVB_FLOW_MODE_FLOW || m == BVB_FLOW_MODE_STALL) flow_cycles += r.cycles, flow_max = std::max(flow_max, r.cycles);
  }
  std::vector<std::string> l = {"frames deciding by flow " + std::to_string(modes[0]) + ", probing " +
                                std::to_string(modes[1]) + ", inside a committed turn " + std::to_string(modes[2]) +
                                ", after a change of the light " + std::to_string(modes[3]) +
                                ", stalled " + std::to_string(modes[4])};
  if (modes[0] + modes[4] && flow_max) {
    char b[200];
    const double mean = flow_cycles / (modes[0] + modes[4]);
    std::snprintf(b, sizeof b,
                  "frames that compute the flow: mean %.0f cycles (%.1f frames/s at 486 MHz, %.1f at 600 MHz), "
                  "max %u",
                  mean, kSrv1Hz / mean, kBf537MaxHz / mean, flow_max);
    l.push_back(b);
  }
  return l;
}

const PipelineDef kFlowAvoid{"flow_avoid",
                             "optical-flow obstacle avoidance (Horn-Schunck, left/right balance)",
                             "pipe_flow_avoid",
                             flow_call,
                             flow_decode,
                             flow_summary};
BVB_PIPELINE(kFlowAvoid);

// ---- the kernel family: the pipeline entry as one kernel ----

void check(Checker &ck) {
  // Each frame starts from the host build's state after the previous one. boxes_approach ends
  // blocked (flow frames, then a committed turn); boxes_turn turns in place (probes only).
  struct Stretch {
    const char *scene;
    int first, count;
  };
  const Stretch stretches[] = {{"boxes_approach", 16, 4}, {"boxes_turn", 0, 3}, {"cylinders_mover", 14, 3}};
  for (const Stretch &s : stretches) {
    Params prm;
    auto frames = pipe::bundled_frames(s.scene, s.first, s.count);
    auto calls = pipe::host_sequence(kFlowAvoid, frames, prm, kState);
    for (size_t i = 0; i < calls.size(); ++i) {
      calls[i].case_name = std::string(s.scene) + " frame " + std::to_string(s.first + int(i));
      ck.add(std::move(calls[i]));
    }
  }
  Params prm;
  auto frames = pipe::render_frames("arena=boxes,path=straight,size=97x61,frames=3,noise=2,uyvy=0,flow=0", 3);
  auto calls = pipe::host_sequence(kFlowAvoid, frames, prm, kState);
  for (size_t i = 0; i < calls.size(); ++i) {
    calls[i].case_name = "boxes 97x61 frame " + std::to_string(i);
    ck.add(std::move(calls[i]));
  }
}

CheckCall bench_call(const std::string &, int w, int h, Rng &) {
  if (!((w == 160 && h == 120) || (w == 320 && h == 240))) return {};
  // The bench scene's two frames (frames/scenes/bench_boxes_WxH: half an inch apart):
  // the second computes the flow.
  Params prm;
  auto calls = pipe::host_sequence(kFlowAvoid, pipe::bench_frames(w, h), prm, kState);
  CheckCall c = std::move(calls[1]);
  c.case_name = size_name(w, h);
  return c;
}

const Family kFlowAvoidFamily{"pipe_flow_avoid", {"pipe_flow_avoid"}, check, bench_call, nullptr, nullptr};
BVB_FAMILY(kFlowAvoidFamily);

}  // namespace
}  // namespace bvb
