#include "pipelines/heldout.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <memory>
#include <random>

#include <unistd.h>

#include "extra_commands.h"
#include "io.h"
#include "options.h"
#include "session/runner.h"
#include "pipelines/odometry.h"
#include "scene/heldout.h"
#include "scene/rng.h"
#include "scene/world.h"
#include "simdriver.h"
#include "target.h"

namespace bvb {

HeldoutLimits heldout_limits() {
  HeldoutLimits l;
  // Collisions per 1,000 closed-loop frames (refused steps, as in the campaigns), over the
  // default 8 arenas of 500 frames. From 200 arenas of one seed on the host build (README,
  // "Held-out scenes"): seg_avoid 0.45 per 1,000 overall, 18 in its worst arena, more than 10
  // per 1,000 in 6 of 100,000 sets of 8 drawn from them; flow_avoid 0.13, 4, and at most 3.
  l.seg_collisions_per_1000 = 10;
  l.flow_collisions_per_1000 = 6;
  // The campaigns' rule: at least a quarter of the frames go forward (the fewest of the sets
  // of 8 above: seg_avoid 47%, flow_avoid 28%).
  l.min_forward_share = 0.25;
  // The odometry over closed polygons, vision alone, 90th percentiles per 100 in driven over
  // the default 10 loops. From 200 loops of one seed: heading 0.28 degrees per 100 in at the
  // median loop, 0.74 at the 90th percentile (the target: 2), 2.17 at worst; the 90th
  // percentile of sets of 10 drawn from them over 2 in 1 of 1,000, 2.17 at most. Position 0.37
  // in per 100 in at the 90th percentile, 0.88 at worst. The profile alone (rot_feat=0) failed
  // every one of 200,000 such sets of its own 200 loops.
  l.odo_heading_p90_per_100in = 3;
  l.odo_position_p90_per_100in = 1.5;
  return l;
}

double nearest_rank(std::vector<double> v, double p) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  size_t k = size_t(std::ceil(p / 100.0 * double(v.size())));
  k = std::clamp<size_t>(k, 1, v.size());
  return v[k - 1];
}

bool avoid_passes(const AvoidTally &t, double max_per_1000, double min_forward_share) {
  return t.frames > 0 && t.per_1000() <= max_per_1000 && t.forward_share() >= min_forward_share;
}

double OdoLoop::heading_per_100in() const { return std::fabs(heading_error_deg) * 100.0 / length_in; }
double OdoLoop::position_per_100in() const { return position_error_in * 100.0 / length_in; }

OdoVerdict odometry_verdict(const std::vector<OdoLoop> &loops, const HeldoutLimits &lim) {
  std::vector<double> h, p, pin;
  for (const OdoLoop &l : loops) {
    h.push_back(l.heading_per_100in());
    p.push_back(l.position_per_100in());
    pin.push_back(l.position_error_in);
  }
  OdoVerdict v;
  v.heading_p50 = nearest_rank(h, 50);
  v.heading_p90 = nearest_rank(h, 90);
  v.position_p50 = nearest_rank(p, 50);
  v.position_p90 = nearest_rank(p, 90);
  v.position_in_p50 = nearest_rank(pin, 50);
  v.position_in_p90 = nearest_rank(pin, 90);
  // NaN (no loops) fails.
  v.pass = v.heading_p90 <= lim.odo_heading_p90_per_100in && v.position_p90 <= lim.odo_position_p90_per_100in;
  return v;
}

namespace {

struct Options {
  std::vector<std::string> pipelines;
  uint64_t seed = 0;
  int runs = 0, frames = 0, only_run = -1;
  std::string impl = "host";
  bool compare_host = false, quiet = false, builds_only = false;
  std::vector<std::string> params;
  Size size{160, 120};
  std::string save_dir;
  int ss = 2;
};

constexpr long long kMaxSeed = 999999999999999999ll;
constexpr int kAvoidScenes = 8, kOdometryLoops = 10;

// $BVB_HELDOUT_SEED, read as --seed would be.
uint64_t env_seed(const char *text) {
  char *end = nullptr;
  errno = 0;
  const long long v = std::strtoll(text, &end, 10);
  if (!std::isdigit(uint8_t(text[0])) || *end || errno == ERANGE || v > kMaxSeed)
    throw UsageError(std::string("BVB_HELDOUT_SEED wants an integer in 0..") + std::to_string(kMaxSeed) + ", got '" +
                     text + "'");
  return uint64_t(v);
}

uint64_t fresh_seed() {
  std::random_device rd;
  const uint64_t t = uint64_t(std::chrono::system_clock::now().time_since_epoch().count());
  return hash_key(uint64_t(rd()) << 32 ^ rd(), t) % 1000000000ull;
}


std::string replay_command(const Options &o, uint64_t seed, int only_run) {
  std::string s = "bfbench heldout";
  for (const auto &p : o.pipelines) s += " " + p;
  s += " --seed " + std::to_string(seed);
  if (o.runs) s += " --runs " + std::to_string(o.runs);
  if (o.frames) s += " --frames " + std::to_string(o.frames);
  if (only_run >= 0) s += " --run " + std::to_string(only_run);
  if (o.impl != "host") s += " --impl " + o.impl;
  if (o.builds_only) s += " --builds-only";
  else if (o.compare_host) s += " --compare-host";
  for (const auto &p : o.params) s += " --param " + p;
  if (size_name(o.size) != "160x120") s += " --size " + size_name(o.size);
  if (o.ss != 2) s += " --ss " + std::to_string(o.ss);
  return s;
}

struct Context {
  const Options &o;
  uint64_t seed;
  const Target *target;
  SceneSpec base;
};

PipelineRun run_scene(const Context &c, const PipelineDef &def, const HeldoutScene &s, bool closed_loop,
                      int max_frames = 0) {
  SceneGenerator gen(s.spec, s.arena);
  Params params;
  for (const auto &p : c.o.params) params.set(p);
  PipelineRunOptions ro;
  ro.impl = c.o.impl;
  ro.compare_host = c.o.compare_host;
  ro.closed_loop = closed_loop;
  ro.max_frames = max_frames;
  ro.progress = isatty(2) != 0;
  return run_pipeline(def, c.target, nullptr, &gen, params, ro);
}

// With --save: the scene's arena file, and the bfbench pipeline command that replays it alone.
void save_scene(const Context &c, const std::string &pipeline, const HeldoutScene &s) {
  if (c.o.save_dir.empty()) return;
  std::filesystem::create_directories(c.o.save_dir);
  const std::string file = c.o.save_dir + "/" + s.name + ".txt";
  const std::string text = format_arena(s.arena);
  write_file_atomic(file, text.data(), text.size());
  SceneSpec spec = s.spec;
  spec.arena = file;
  // The keys that differ from a default spec's (format_scene_spec lists every key in order).
  const std::vector<std::string> mine = split_list(format_scene_spec(spec)),
                                 plain = split_list(format_scene_spec(SceneSpec{}));
  std::string keys;
  for (size_t i = 0; i < mine.size(); ++i)
    if (i >= plain.size() || mine[i] != plain[i]) keys += (keys.empty() ? "" : ",") + mine[i];
  std::printf("    replay alone: bfbench pipeline %s%s --impl %s --spec %s\n", pipeline.c_str(),
              s.spec.path == "avoid" ? " --closed-loop" : "", c.o.impl.c_str(), keys.c_str());
}

bool differs(const std::string &name, int k, const PipelineRun &run) {
  if (run.mismatches.empty()) return false;
  std::printf("    %s scene %d: host and Blackfin builds differ in %zu frames; first: %s\n", name.c_str(), k,
              run.mismatches.size(), run.mismatches[0].c_str());
  return true;
}

int scene_count(const Options &o, int fallback) { return o.runs ? o.runs : fallback; }

bool judge_avoid(const Context &c, const std::string &name, double limit) {
  const PipelineDef *def = find_pipeline(name);
  const int runs = scene_count(c.o, kAvoidScenes), frames = c.o.frames ? c.o.frames : 500;
  AvoidTally t;
  bool same = true;
  for (int k = 0; k < runs; ++k) {
    if (c.o.only_run >= 0 && k != c.o.only_run) continue;
    const HeldoutScene s = heldout_avoid_scene(c.seed, k, frames, c.base);
    const PipelineRun run = run_scene(c, *def, s, true);
    int forward = 0;
    for (const auto &r : run.frames) forward += r.out.has_decision && r.out.decision == Drive::Forward;
    t.frames += int(run.frames.size());
    t.collisions += run.collisions;
    t.forward += forward;
    if (!c.o.quiet)
      std::printf("  %s scene %d: %s: %zu frames, %d collisions, %d forward\n", name.c_str(), k, s.describe().c_str(),
                  run.frames.size(), run.collisions, forward);
    save_scene(c, name, s);
    same = !differs(name, k, run) && same;
  }
  const bool pass = (c.o.builds_only || avoid_passes(t, limit, heldout_limits().min_forward_share)) && same;
  std::printf("%s: %d frames, %d collisions: %.2f per 1,000 frames (limit %.2f), %.0f%% forward (at least %.0f%%)%s: %s\n",
              name.c_str(), t.frames, t.collisions, t.per_1000(), limit, 100 * t.forward_share(),
              100 * heldout_limits().min_forward_share, c.o.builds_only ? ", not judged (--builds-only)" : "",
              pass ? "pass" : "FAIL");
  return pass;
}

bool judge_odometry(const Context &c) {
  const PipelineDef *def = find_pipeline("odometry");
  const int runs = scene_count(c.o, kOdometryLoops);
  std::vector<OdoLoop> loops;
  bool same = true;
  for (int k = 0; k < runs; ++k) {
    if (c.o.only_run >= 0 && k != c.o.only_run) continue;
    const HeldoutScene s = heldout_odometry_scene(c.seed, k, c.base);
    // --frames cuts a loop only where nothing but the builds' equality is judged.
    const PipelineRun run = run_scene(c, *def, s, false, c.o.builds_only ? c.o.frames : 0);
    const FrameRecord &last = run.frames.back();
    OdoLoop l;
    l.length_in = s.polygon.length_in();
    l.position_error_in = std::hypot(last.out.x_in - last.in.truth.pose.x_in, last.out.y_in - last.in.truth.pose.y_in);
    l.heading_error_deg = last.out.heading_deg - last.in.truth.pose.heading_deg;
    for (const OdoSegment &seg : odometry_segments(run.frames)) {
      if (seg.turn) l.worst_turn_deg = std::max(l.worst_turn_deg, std::fabs(seg.error));
      else l.worst_leg_pct = std::max(l.worst_leg_pct, std::fabs(seg.error));
    }
    loops.push_back(l);
    if (!c.o.quiet)
      std::printf("  odometry scene %d: %s: final error %.2f in, %+.2f deg (%.2f in, %.2f deg per 100 in); "
                  "worst turn %.2f deg, worst leg %.2f%%\n",
                  k, s.describe().c_str(), l.position_error_in, l.heading_error_deg, l.position_per_100in(),
                  l.heading_per_100in(), l.worst_turn_deg, l.worst_leg_pct);
    save_scene(c, "odometry", s);
    same = !differs("odometry", k, run) && same;
  }
  const HeldoutLimits lim = heldout_limits();
  const OdoVerdict v = odometry_verdict(loops, lim);
  const bool pass = (c.o.builds_only || v.pass) && same;
  std::printf("odometry: %zu loops: final heading error per 100 in p50 %.2f, p90 %.2f deg (limit %.2f); final "
              "position error per 100 in p50 %.2f, p90 %.2f in (limit %.2f; in inches p50 %.2f, p90 %.2f)%s: %s\n",
              loops.size(), v.heading_p50, v.heading_p90, lim.odo_heading_p90_per_100in, v.position_p50,
              v.position_p90, lim.odo_position_p90_per_100in, v.position_in_p50, v.position_in_p90,
              c.o.builds_only ? ", not judged (--builds-only)" : "", pass ? "pass" : "FAIL");
  return pass;
}

int heldout_main(int argc, char **argv) {
  Options o;
  long long seed = 0;
  const HeldoutLimits l = heldout_limits();
  char limits[256];
  std::snprintf(limits, sizeof limits,
                "limits: seg_avoid %.2f and flow_avoid %.2f collisions per 1,000 frames; odometry p90 %.2f deg and "
                "%.2f in per 100 in driven",
                l.seg_collisions_per_1000, l.flow_collisions_per_1000, l.odo_heading_p90_per_100in,
                l.odo_position_p90_per_100in);
  CommandLine cl("heldout");
  cl.about("Judges the pipelines (seg_avoid, flow_avoid, odometry; all three by default) on scenes\n"
           "drawn afresh from a seed: arenas (room, obstacles, floor colour, light), floor texture\n"
           "seeds, start poses and, for the odometry, closed polygons of 3 to 8 sides and 12 to 36 in\n"
           "legs. The seed is --seed N, else $BVB_HELDOUT_SEED, else new each run (time and\n"
           "random_device); it is printed with the command that replays the run.\n"
           "  seg_avoid, flow_avoid: --runs arenas (default 8) of --frames closed-loop frames (500);\n"
           "      passes at most the limit of collisions (refused steps) per 1,000 frames, and at least\n"
           "      a quarter of the frames forward.\n"
           "  odometry: --runs polygons (default 10), vision alone unless --param fuse=1; passes when\n"
           "      the 90th percentiles (nearest rank) of the final heading error and the final position\n"
           "      error per 100 in driven are within their limits.\n"
           "--frames also cuts each odometry loop, with --builds-only only. --impl is host by default\n"
           "(every build computes the same frames: --compare-host checks it). --builds-only (implies\n"
           "--compare-host) judges only that: a few scenes on the simulator say little about a rate,\n"
           "the host run's many do, and equal frames make them the Blackfin's.")
      .operands("PIPELINE", &o.pipelines, 0, 100, "(seg_avoid, flow_avoid or odometry)")
      .integer("--seed", "N", 0, kMaxSeed, &seed, "the seed the scenes are drawn from")
      .integer("--runs", "N", 1, 10000, &o.runs, "scenes per pipeline (default 8 arenas, 10 polygons)")
      .integer("--frames", "N", 1, 100000, &o.frames, "closed-loop frames per arena (default 500)")
      .integer("--run", "K", 0, 9999, &o.only_run, "only scene K (0-based) of each pipeline")
      .text("--impl", "host|c|asm", &o.impl, "the build (default host)")
      .flag("--compare-host", &o.compare_host, "every frame of a Blackfin build compared with the host build's")
      .texts("--param", "K=V", &o.params, "a pipeline parameter (with exactly one PIPELINE)")
      .size("--size", &o.size, "the scenes' frame size (default 160x120)")
      .integer("--ss", "N", 1, 8, &o.ss, "the scenes' supersampling (default 2)")
      .text("--save", "DIR", &o.save_dir,
            "write each scene's arena file there and print the bfbench pipeline command that replays it")
      .flag("--builds-only", &o.builds_only, "judge only that the builds agree (implies --compare-host)")
      .flag("--quiet", &o.quiet, "the verdicts only, not a line per scene")
      .tail(limits)
      .exit_status("Exit status 0 all within the limits, 1 a pipeline outside them (or builds that differ), "
                   "2 bad usage, bad input or a set-up that cannot run.");
  if (!cl.parse(argc, argv)) return kExitOk;
  o.compare_host = o.compare_host || o.builds_only;
  if (o.impl != "host") parse_impl(o.impl);
  if (o.save_dir.find(',') != std::string::npos) throw UsageError("--save: a directory without commas, please (it goes into a scene spec)");
  if (o.pipelines.empty()) o.pipelines = {"seg_avoid", "flow_avoid", "odometry"};
  for (const auto &p : o.pipelines)
    if (p != "seg_avoid" && p != "flow_avoid" && p != "odometry")
      throw UsageError("unknown pipeline '" + p + "' (seg_avoid, flow_avoid or odometry)");
  if (o.frames && !o.builds_only && std::find(o.pipelines.begin(), o.pipelines.end(), "odometry") != o.pipelines.end())
    throw UsageError("--frames would cut the odometry's loops, which are judged whole: give it with --builds-only, "
                     "or for seg_avoid and flow_avoid alone");
  if (o.builds_only && o.impl == "host") throw UsageError("--builds-only compares a Blackfin build: give --impl c or asm");
  if (!o.params.empty() && o.pipelines.size() != 1) throw UsageError("--param needs exactly one PIPELINE");
  if (o.only_run >= 0 && o.only_run >= scene_count(o, o.pipelines[0] == "odometry" ? kOdometryLoops : kAvoidScenes))
    throw UsageError("--run " + std::to_string(o.only_run) + " is past the last scene");

  uint64_t the_seed;
  const char *env = std::getenv("BVB_HELDOUT_SEED");
  if (cl.given("--seed")) the_seed = uint64_t(seed);
  else if (env && *env) the_seed = env_seed(env);
  else the_seed = fresh_seed();
  // The scenes' size and rendering, checked as a scene spec would be.
  SceneSpec base = parse_scene_spec("size=" + size_name(o.size) + ",ss=" + std::to_string(o.ss) + ",uyvy=0,flow=0");

  std::unique_ptr<Target> target;
  if (o.impl != "host" || o.compare_host) target = std::make_unique<Target>(product_firmware(), default_simulator());
  std::printf("held-out seed %llu (%s)\n", static_cast<unsigned long long>(the_seed),
              cl.given("--seed") ? "--seed" : env && *env ? "BVB_HELDOUT_SEED" : "drawn for this run");
  std::printf("replay: %s\n", replay_command(o, the_seed, o.only_run).c_str());
  std::fflush(stdout);
  Context c{o, the_seed, target.get(), base};
  const HeldoutLimits lim = heldout_limits();
  bool pass = true;
  for (const auto &p : o.pipelines) {
    if (p == "seg_avoid") pass = judge_avoid(c, p, lim.seg_collisions_per_1000) && pass;
    if (p == "flow_avoid") pass = judge_avoid(c, p, lim.flow_collisions_per_1000) && pass;
    if (p == "odometry") pass = judge_odometry(c) && pass;
    std::fflush(stdout);
  }
  if (!pass) std::printf("replay: %s\n", replay_command(o, the_seed, o.only_run).c_str());
  return pass ? kExitOk : kExitFailed;
}

}  // namespace

int heldout_command(int argc, char **argv) {
  return run_command("heldout", [&] { return heldout_main(argc, argv); });
}

}  // namespace bvb

namespace bvb {
// In this tree's bfbench only: the command runs this tree's pipelines.
static const bool kHeldoutRegistered = register_extra_command(
    "heldout", "the pipelines on scenes drawn afresh from a printed seed, judged on rates", heldout_command);
}  // namespace bvb
