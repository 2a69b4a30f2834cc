// bfbench pipeline odometry, and the pipe_odometry kernel's family (check, bench, run).
//
// Parameters (--param K=V; defaults scale with the frame, shown at 160x120):
//   tracker=lk|ncc [lk]   fuse=0|1 [0]   features=N [32]   min_dist=PX [8]   harris_thr=R [300]
//   max_range=IN [24]     levels=N [3]   win=PX [7]        iters=N [10]
//   ncc_r=PX [5]          ncc_s=PX [8]   ncc_sub=0|1 [1]
//   inlier_tol=MIL [100]  min_inliers=N [5]   (MIL: thousandths of an inch)
//   tpi=N [50]            wheelbase=MIL [4000]   rot_tol=MDEG [1000]   trans_tol=MIL [100]
//   band_y0=ROW band_rows=N [rows around the horizon]  win_x0=COL win_w=N rho=N
// tpi and wheelbase describe the robot's encoders; they must match the scene's (the scene
// generator's defaults are 50 ticks per inch and a 4 in wheelbase).
#include "pipelines/odometry.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "bvb/ncc.h"
#include "bvb/scanline.h"
#include "io.h"
#include "pipe_common.h"
#include "patterns.h"
#include "scene/scene_io.h"
#include "formats.h"
#include "names.h"

namespace bvb {

namespace {

int32_t q16(double v) { return int32_t(std::lround(v * 65536.0)); }
int32_t q8(double v) { return int32_t(std::lround(v * 256.0)); }

template <class T> std::vector<uint8_t> as_bytes(const T *p, size_t n) {
  std::vector<uint8_t> b(n * sizeof(T));
  std::memcpy(b.data(), p, b.size());
  return b;
}

}  // namespace

bvb_odo_params odometry_params(const Camera &cam, Params &params, const Pose &start) {
  const int w = cam.width, h = cam.height;
  const double sx = w / 160.0;
  bvb_odo_params p{};
  p.fx = q8(cam.fx);
  p.fy = q8(cam.fy);
  p.cx = q8(cam.cx);
  p.cy = q8(cam.cy);
  p.cam_height = q16(cam.cam_height_in);
  p.tilt = q16(cam.tilt_deg);
  p.cam_offset = q16(cam.cam_offset_in);
  p.start_x = q16(start.x_in);
  p.start_y = q16(start.y_in);
  p.start_heading = q16(start.heading_deg);

  // The band: about a quarter of the frame's rows around the horizon, where distant walls and
  // obstacles give a profile that a forward step barely changes.
  const double horizon = cam.cy - cam.fy * std::tan(deg2rad(cam.tilt_deg));
  const int rows_def = std::max(1, std::min(BVB_SCANLINE_MAX_ROWS, (h * 32 + 60) / 120));
  const int y0_def = std::clamp(int(std::lround(horizon)) - rows_def * 7 / 16, 0, h - rows_def);
  p.band_rows = params.get_int("band_rows", rows_def, 1, std::min(h, BVB_SCANLINE_MAX_ROWS));
  p.band_y0 = params.get_int("band_y0", std::min(y0_def, h - p.band_rows), 0, h - p.band_rows);
  const int x0_def = w / 20;
  p.win_x0 = params.get_int("win_x0", x0_def, 0, w - 1);
  p.win_w = params.get_int("win_w", std::min(w - 2 * p.win_x0, BVB_SCANLINE_MAX_WINDOW), 1,
                           std::min(w - p.win_x0, BVB_SCANLINE_MAX_WINDOW));
  p.rho = params.get_int("rho", std::max(1, p.win_w - int(std::lround(40 * sx))), 1, p.win_w);

  p.shift_fit = params.get_int("shift_fit", 1, 0, 2);
  p.rot_bins = params.get_int("rot_bins", 1, 0, 1);
  p.key_shift = params.get_int("key_shift", std::max(1, int(std::lround(24 * sx))), 1, 1024);
  p.key_frames = params.get_int("key_frames", 8, 1, 1000000);
  p.key_still = params.get_int("key_still", 2, 0, 1024);
  const std::string tracker = params.get_str("tracker", "lk");
  if (tracker != "lk" && tracker != "ncc") throw InputError("parameter tracker=" + tracker + ": want lk or ncc");
  p.tracker = tracker == "lk" ? BVB_ODO_TRACK_LK : BVB_ODO_TRACK_NCC;
  p.max_range = q16(params.get_int("max_range", 24, 1, 256));
  p.max_features = params.get_int("features", 32, 1, BVB_ODO_MAX_FEATURES);
  p.min_distance = params.get_int("min_dist", std::max(1, int(std::lround(8 * sx))), 0, 1024);
  p.harris_threshold = params.get_int("harris_thr", 300, 0, 1 << 30);
  p.lk_levels = params.get_int("levels", w >= 320 ? 4 : 3, 1, 4);
  p.lk_win = params.get_int("win", 7, 3, 15);
  if ((p.lk_win & 1) == 0) throw InputError("parameter win: want an odd size");
  p.lk_max_iter = params.get_int("iters", 10, 1, 100);
  p.lk_eps = 655;  // 0.01 px
  p.lk_min_det = 1;
  p.ncc_radius = params.get_int("ncc_r", 5, 1, BVB_NCC_MAX_RADIUS);
  p.ncc_search = params.get_int("ncc_s", std::min(BVB_NCC_MAX_SEARCH, int(std::lround(8 * sx))), 1,
                                BVB_NCC_MAX_SEARCH);
  p.ncc_subpixel = params.get_int("ncc_sub", 1, 0, 1);
  p.inlier_tol = q16(params.get_int("inlier_tol", 100, 0, 64000) / 1000.0);
  p.min_inliers = params.get_int("min_inliers", 5, 1, BVB_ODO_MAX_FEATURES);
  p.fuse = params.get_int("fuse", 0, 0, 1);
  p.tpi = params.get_int("tpi", 50, 1, 65535) * 256;
  p.wheelbase = q16(params.get_int("wheelbase", 4000, 100, 256000) / 1000.0);
  p.fuse_rot_tol = q16(params.get_int("rot_tol", 1000, 0, 360000) / 1000.0);
  p.fuse_trans_tol = q16(params.get_int("trans_tol", 100, 0, 64000) / 1000.0);
  p.fuse_window = params.get_int("fuse_window", 16, 1, 1000000);
  p.rot_feat = params.get_int("rot_feat", 1, 0, 1);
  p.rot_small = q16(params.get_int("rot_small", 4500, 0, 90000) / 1000.0);
  p.rot_min_inliers = params.get_int("rot_min_inliers", 8, 2, BVB_ODO_MAX_FEATURES);
  p.rot_sel_tol = q16(params.get_int("rot_sel_tol", 250, 0, 64000) / 1000.0);
  if (bvb_pipe_odometry_state_bytes(w, h, w, &p) == 0)
    throw InputError("odometry: parameters out of range for this camera");
  return p;
}

CheckCall odometry_call(const Image &grey, int stride, const bvb_pipe_frame &info, const bvb_odo_params &p,
                        std::vector<uint8_t> state, bool persistent, const std::string &name) {
  const int w = grey.width, h = grey.height;
  std::vector<uint8_t> frame(size_t(stride) * h, 0);
  for (int y = 0; y < h; ++y) std::memcpy(&frame[size_t(y) * stride], &grey.data[size_t(y) * w], size_t(w));
  const size_t sbytes = bvb_pipe_odometry_state_bytes(w, h, stride, &p);
  const size_t xbytes = bvb_pipe_odometry_work_bytes(w, h, stride, &p);
  if (sbytes == 0) throw InputError("odometry: parameters out of range for " + size_name(w, h));
  if (state.empty()) state.assign(sbytes, 0);
  CheckCall c;
  c.kernel = "pipe_odometry";
  c.case_name = name;
  c.pixels = double(w) * h;
  int ifr = c.in("frame", std::move(frame), View{1, false, w, h, stride});
  int iin = c.in("info", pipe::bytes_of(info), View{4, true});
  int ip = c.in("params", pipe::bytes_of(p), View{4, true});
  int ist = c.inout("state", std::move(state), View{4, true});
  int ir = c.out("result", sizeof(bvb_pipe_result), View{4, true});
  int ix = c.scratch("work", xbytes);
  // The working rows that want L1 (the Harris scratch and at 160x120 the pyramid: 13 KB; 13.4 KB
  // at 320x240 without it) in data
  // bank B, as the robot's build places them; everything else in SDRAM. The checks place
  // every buffer at random over this.
  const size_t fbytes = bvb_pipe_odometry_fast_bytes(w, h, stride, &p);
  int ifa = c.scratch("fast", fbytes);
  if (fbytes <= BVB_ODO_FAST_MAX) c.bufs[size_t(ifa)].place = BVB_PLACE_L1B;
  c.bufs[size_t(ist)].persistent = persistent;
  c.buf(ifr).word(w).word(h).word(stride).buf(iin).buf(ip).buf(ist).buf(ir).buf(ix).buf(ifa);
  c.host = [=](HostBuffers &m) {
    m.set_ret(bvb_pipe_odometry_c(m.u8(ifr), w, h, stride, m.as<bvb_pipe_frame>(iin), m.as<bvb_odo_params>(ip),
                                  m.u8(ist), m.as<bvb_pipe_result>(ir), m.u8(ix), m.u8(ifa)));
  };
  return c;
}

std::vector<OdoSegment> odometry_segments(const std::vector<FrameRecord> &fr) {
  std::vector<OdoSegment> segs;
  auto kind = [](const FrameTruth &t) {
    if (t.step.turn_deg != 0 && t.step.forward_in == 0) return 1;
    if (t.step.forward_in != 0) return 2;
    return 0;
  };
  size_t f = 1;
  while (f < fr.size()) {
    const int k = kind(fr[f].in.truth);
    size_t e = f;
    while (e + 1 < fr.size() && kind(fr[e + 1].in.truth) == k) ++e;
    if (k != 0) {
      OdoSegment s;
      s.turn = k == 1;
      s.first = int(f - 1);
      s.last = int(e);
      const auto &a = fr[f - 1], &b = fr[e];
      if (s.turn) {
        s.true_value = b.in.truth.pose.heading_deg - a.in.truth.pose.heading_deg;
        s.est_value = b.out.heading_deg - a.out.heading_deg;
        s.error = s.est_value - s.true_value;
      } else {
        s.true_value = std::hypot(b.in.truth.pose.x_in - a.in.truth.pose.x_in, b.in.truth.pose.y_in - a.in.truth.pose.y_in);
        s.est_value = std::hypot(b.out.x_in - a.out.x_in, b.out.y_in - a.out.y_in);
        s.error = 100.0 * (s.est_value - s.true_value) / s.true_value;
      }
      segs.push_back(s);
    }
    f = e + 1;
  }
  return segs;
}

namespace {

FrameOutput decode(const std::vector<std::vector<uint8_t>> &bufs) {
  const bvb_pipe_result r = pipe::from_bytes<bvb_pipe_result>(bufs[kOdoResultBuf]);
  const int32_t *d = r.diag;
  const uint32_t points = uint32_t(d[BVB_ODO_DIAG_POINTS]);
  FrameOutput o;
  o.has_pose = r.has_pose != 0;
  o.x_in = r.x_q16 / 65536.0;
  o.y_in = r.y_q16 / 65536.0;
  o.heading_deg = r.heading_q16 / 65536.0;
  o.diag = {{"stages", double(d[BVB_ODO_DIAG_STAGES])},
            {"dtheta_vis_deg", d[BVB_ODO_DIAG_DTHETA_VIS] / 65536.0},
            {"dtheta_enc_deg", d[BVB_ODO_DIAG_DTHETA_ENC] / 65536.0},
            {"dtheta_deg", d[BVB_ODO_DIAG_DTHETA] / 65536.0},
            {"dfwd_vis_in", d[BVB_ODO_DIAG_DFWD_VIS] / 65536.0},
            {"dfwd_enc_in", d[BVB_ODO_DIAG_DFWD_ENC] / 65536.0},
            {"dfwd_in", d[BVB_ODO_DIAG_DFWD] / 65536.0},
            {"flags", double(points & 255)},
            {"inliers", double(points >> 8 & 255)},
            {"tracked", double(points >> 16 & 255)},
            {"detected", double(points >> 24)}};
  return o;
}

std::vector<std::string> summarize(const std::vector<FrameRecord> &fr) {
  std::vector<std::string> lines;
  char b[200];
  int turns = 0, legs = 0, rot_enc = 0, fwd_enc = 0, fwd_none = 0;
  double worst_turn = 0, worst_leg = 0;
  for (const OdoSegment &s : odometry_segments(fr)) {
    if (s.turn) {
      std::snprintf(b, sizeof b, "turn %d (frames %d-%d): true %.2f deg, estimated %.2f deg, error %+.2f deg",
                    ++turns, s.first, s.last, s.true_value, s.est_value, s.error);
      worst_turn = std::max(worst_turn, std::fabs(s.error));
    } else {
      std::snprintf(b, sizeof b, "leg %d (frames %d-%d): true %.2f in, estimated %.2f in, error %+.2f%%", ++legs,
                    s.first, s.last, s.true_value, s.est_value, s.error);
      worst_leg = std::max(worst_leg, std::fabs(s.error));
    }
    lines.push_back(b);
  }
  for (const auto &r : fr)
    for (const auto &d : r.out.diag)
      if (d.first == "flags") {
        const int f = int(d.second);
        rot_enc += (f & BVB_ODO_F_ROT_ENC) != 0;
        fwd_enc += (f & BVB_ODO_F_FWD_ENC) != 0;
        fwd_none += (f & BVB_ODO_F_FWD_NONE) != 0;
      }
  if (turns) {
    std::snprintf(b, sizeof b, "rotation: worst turn error %.2f deg", worst_turn);
    lines.push_back(b);
  }
  if (legs) {
    std::snprintf(b, sizeof b, "translation: worst leg error %.2f%%", worst_leg);
    lines.push_back(b);
  }
  std::snprintf(b, sizeof b, "frames using the encoders: rotation %d, translation %d; without a visual translation %d",
                rot_enc, fwd_enc, fwd_none);
  lines.push_back(b);
  // Dead reckoning from the encoders alone, for comparison (the firmware's per-frame values).
  if (!fr.empty()) {
    Pose e = fr[0].in.truth.pose;
    for (size_t i = 1; i < fr.size(); ++i) {
      double dfwd = 0, dth = 0;
      for (const auto &d : fr[i].out.diag) {
        if (d.first == "dfwd_enc_in") dfwd = d.second;
        if (d.first == "dtheta_enc_deg") dth = d.second;
      }
      const double hm = deg2rad(e.heading_deg + dth / 2);
      e.x_in += dfwd * std::cos(hm);
      e.y_in += dfwd * std::sin(hm);
      e.heading_deg += dth;
    }
    const Pose &t = fr.back().in.truth.pose;
    std::snprintf(b, sizeof b, "encoders alone: final pose error %.2f in, %.2f deg", std::hypot(e.x_in - t.x_in, e.y_in - t.y_in),
                  e.heading_deg - t.heading_deg);
    lines.push_back(b);
  }
  return lines;
}

CheckCall make_call(const FrameInput &in, Params &params) {
  // The pose starts where the robot starts (frame 0); the firmware reads it only then.
  static Pose start;
  if (in.index == 0) start = in.truth.pose;
  const bvb_odo_params p = odometry_params(*in.camera, params, start);
  const bvb_pipe_frame info = pipe::frame_info(in, params.get_int("stages", 0, 0, BVB_ODO_STAGES));
  return odometry_call(*in.grey, in.grey->width, info, p, {}, true, "frame " + std::to_string(in.index));
}

const PipelineDef kOdometry{"odometry",
                            "visual odometry: profile-shift rotation, floor-feature translation, "
                            "optional encoder fusion (pose vs truth)",
                            "pipe_odometry", make_call, decode, summarize};
BVB_PIPELINE(kOdometry);

// ---- the kernel family: host C = Blackfin C = assembly on short rendered scenes ----

struct Sequence {
  std::string spec;
  std::vector<std::pair<std::string, std::string>> params;
  int stride_pad = 0;
};

// Renders the scene and queues one call per frame, each starting from the state the host
// reference left after the previous frame.
void check_sequence(Checker &ck, const Sequence &q) {
  SceneGenerator gen(parse_scene_spec(q.spec));
  Params params;
  for (const auto &kv : q.params) params.set(kv.first + "=" + kv.second);
  const bvb_odo_params p = odometry_params(gen.camera(), params, gen.pose());
  // The state's contents before frame 0 do not matter (the contract): start from noise.
  const int stride0 = gen.camera().width + q.stride_pad;
  std::vector<uint8_t> state(bvb_pipe_odometry_state_bytes(gen.camera().width, gen.camera().height, stride0, &p));
  for (auto &v : state) v = uint8_t(ck.rng().u32());
  std::string label = q.spec;
  for (const auto &kv : q.params) label += " " + kv.first + "=" + kv.second;
  for (int f = 0; f < gen.frames(); ++f) {
    const Image grey = gen.render().grey;
    const FrameTruth t = gen.truth();
    FrameInput fi;
    fi.index = f;
    fi.truth = t;
    const bvb_pipe_frame info = pipe::frame_info(fi, 0);
    const int stride = grey.width + q.stride_pad;
    CheckCall c = odometry_call(grey, stride, info, p, state, false,
                                label + " stride " + std::to_string(stride) + " frame " + std::to_string(f));
    // The host's state after this frame starts the next call.
    std::vector<std::vector<uint8_t>> bufs;
    for (const auto &b : c.bufs) bufs.push_back(b.data);
    HostBuffers hb(bufs);
    c.host(hb);
    state = bufs[kOdoStateBuf];
    ck.place_randomly(c);
    ck.add(std::move(c));
    if (f + 1 < gen.frames()) gen.advance();
  }
}

void check(Checker &ck) {
  Rng &rng = ck.rng();
  const std::string seed = std::to_string(rng.uniform(1, 1000));
  std::vector<Sequence> seqs = {
      {"arena=boxes,path=F1.5+L6+R3,ss=1,noise=2,seed=" + seed, {}, 0},
      // Fusion with tight tolerances, so that every rule fires: the encoders slip and a
      // moving object crosses the view.
      {"arena=boxes,path=F1+R6,ss=1,mover=cross,slip=0.05,enc_noise=1,seed=" + seed,
       {{"tracker", "ncc"}, {"fuse", "1"}, {"rot_tol", "150"}, {"trans_tol", "20"}, {"fuse_window", "2"}}, 3},
      {"arena=boxes,path=L3+F1,ss=1,size=96x72,seed=" + seed,
       {{"fuse", "1"}, {"levels", "2"}, {"win", "5"}, {"rot_bins", "0"}, {"shift_fit", "2"}}, 1},
      // A longer run at a small size: key profiles renewed by shift, by age and while still,
      // the fusion window, features lost at the borders.
      {"arena=cylinders,path=F3+L30+F2,ss=1,size=48x36,slip=0.1,seed=" + seed,
       {{"tracker", "ncc"}, {"ncc_r", "2"}, {"ncc_s", "3"}, {"features", "8"}, {"fuse", "1"},
        {"rot_tol", "300"}, {"fuse_window", "4"}, {"key_shift", "6"}, {"key_frames", "3"}}, 0},
  };
  if (ck.options().campaign) {
    seqs.push_back({"arena=corridor,path=F1+L3,ss=1,size=320x240,seed=" + seed, {}, 4});
    seqs.push_back({"arena=boxes,path=R3,ss=1,size=640x480,seed=" + seed, {{"tracker", "ncc"}}, 0});
    seqs.push_back({"arena=boxes,path=F1+L3,ss=1,size=33x25,uyvy=0,seed=" + seed,
                    {{"ncc_r", "1"}, {"ncc_s", "2"}, {"levels", "1"}, {"win", "3"}, {"max_range", "40"}}, 2});
    seqs.push_back({"arena=boxes,path=F0.5+R3,ss=1,size=16x16,seed=" + seed,
                    {{"levels", "1"}, {"win", "3"}, {"max_range", "200"}}, 0});
  }
  for (const Sequence &q : seqs) check_sequence(ck, q);
}

// The bench scene's two frames at w x h (frames/scenes/bench_boxes_WxH: half an inch
// apart): the call for the second frame, its state as the first frame left it.
CheckCall bench_call(const std::string &, int w, int h, Rng &) {
  const std::vector<pipe::SceneFrame> frames = pipe::bench_frames(w, h);
  Params params;
  const bvb_odo_params p = odometry_params(frames[0].camera, params, frames[0].truth.pose);
  std::vector<uint8_t> state;
  CheckCall c;
  for (int f = 0; f < 2; ++f) {
    FrameInput fi;
    fi.index = f;
    fi.truth = frames[size_t(f)].truth;
    const bvb_pipe_frame info = pipe::frame_info(fi, 0);
    c = odometry_call(frames[size_t(f)].grey, w, info, p, state, false, size_name(w, h));
    if (f == 0) {
      std::vector<std::vector<uint8_t>> bufs;
      for (const auto &b : c.bufs) bufs.push_back(b.data);
      HostBuffers hb(bufs);
      c.host(hb);
      state = bufs[kOdoStateBuf];
    }
  }
  return c;
}

double lower_bound(const std::string &, int, int) { return 0; }

// bfbench run odometry --in A --in B: the motion from frame A to frame B, with the standard
// camera of the frames' size (camera.h) unless --param says otherwise.
RunPlan plan_run(RunRequest &req) {
  if (req.inputs.size() != 2) throw InputError("odometry takes two --in frames (previous, current)");
  const Image a = read_input(req, 0);
  const Image b = read_input(req, 1);
  if (a.width != b.width || a.height != b.height) throw InputError("odometry: the two frames differ in size");
  Camera cam = Camera::standard(a.width, a.height);
  cam.cam_height_in = req.params.get_int("cam_height_mil", 4000, 100, 64000) / 1000.0;
  cam.tilt_deg = req.params.get_int("tilt_mdeg", 10000, -45000, 45000) / 1000.0;
  const bvb_odo_params p = odometry_params(cam, req.params, Pose{});
  const int stages = req.params.get_int("stages", 0, 0, BVB_ODO_STAGES);
  req.params.check_all_used();
  const bvb_pipe_frame info0{0, 0, 0, 0}, info1{1, 0, 0, stages};
  CheckCall first = odometry_call(a, a.width, info0, p, {}, false, "run");
  std::vector<std::vector<uint8_t>> bufs;
  for (const auto &bb : first.bufs) bufs.push_back(bb.data);
  HostBuffers hb(bufs);
  first.host(hb);
  RunPlan plan;
  plan.call = odometry_call(b, b.width, info1, p, bufs[kOdoStateBuf], false, "run");
  plan.write = [](std::vector<std::vector<uint8_t>> &out, const std::string &path) {
    FrameOutput o = decode(out);
    std::string s = "key,value\n";
    char line[96];
    for (const auto &d : o.diag) {
      std::snprintf(line, sizeof line, "%s,%.6f\n", d.first.c_str(), d.second);
      s += line;
    }
    write_text_output(path, s);
  };
  plan.kind = OutputKind::Text;
  plan.summary = size_name(a.width, a.height) + ", the motion between two frames";
  return plan;
}

const Family kOdometryFamily{"pipe_odometry", {"pipe_odometry"}, check, bench_call, lower_bound, plan_run};
BVB_FAMILY(kOdometryFamily);

}  // namespace
}  // namespace bvb
