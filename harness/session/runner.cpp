#include "runner.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <sstream>

#include <unistd.h>

#include "io.h"
#include "options.h"
#include "patterns.h"
#include "simdriver.h"
#include "svg.h"
#include "target.h"

namespace bvb {

std::vector<const PipelineDef *> &pipelines() {
  static std::vector<const PipelineDef *> p;
  return p;
}

bool register_pipeline(const PipelineDef *p) {
  pipelines().push_back(p);
  return true;
}

const PipelineDef *find_pipeline(const std::string &name) {
  for (const PipelineDef *p : pipelines())
    if (p->name == name) return p;
  return nullptr;
}

const char *drive_name(Drive d) {
  switch (d) {
    case Drive::Stop: return "stop";
    case Drive::Forward: return "forward";
    case Drive::Left: return "left";
    case Drive::Right: return "right";
  }
  return "?";
}

namespace {

std::string compare_outputs(const FrameOutput &a, const FrameOutput &b) {
  std::ostringstream o;
  if (a.has_decision != b.has_decision || a.decision != b.decision)
    o << "decision " << drive_name(a.decision) << " vs " << drive_name(b.decision) << "; ";
  if (a.has_pose != b.has_pose || a.x_in != b.x_in || a.y_in != b.y_in || a.heading_deg != b.heading_deg)
    o << "pose (" << a.x_in << ", " << a.y_in << ", " << a.heading_deg << ") vs (" << b.x_in << ", " << b.y_in
      << ", " << b.heading_deg << "); ";
  if (a.diag.size() == b.diag.size())
    for (size_t i = 0; i < a.diag.size(); ++i)
      if (a.diag[i].second != b.diag[i].second)
        o << a.diag[i].first << " " << a.diag[i].second << " vs " << b.diag[i].second << "; ";
  return o.str();
}

// The host build's buffers: persistent ones keep what the previous frame left.
void refresh_host_buffers(std::vector<std::vector<uint8_t>> &host, const CheckCall &cc, bool first) {
  if (first) host.clear();
  for (size_t b = 0; b < cc.bufs.size(); ++b) {
    if (first) host.push_back(cc.bufs[b].data);
    else if (!cc.bufs[b].persistent) host[b] = cc.bufs[b].data;
  }
}

}  // namespace

PipelineRun run_pipeline(const PipelineDef &def, const Target *target, const SceneData *dir,
                         SceneGenerator *gen, Params &params, const PipelineRunOptions &opts) {
  const bool on_target = opts.impl != "host";
  const KernelInfo &k = Registry::product().get(def.kernel);
  uint32_t impl = BVB_IMPL_C;
  if (on_target) {
    impl = parse_impl(opts.impl);
    if (impl == BVB_IMPL_ASM && !k.has_asm)
      throw InputError("pipeline " + def.name + " has no assembly build (use --impl c)");
  }
  std::unique_ptr<Session> session;
  if (on_target) session = std::make_unique<Session>(*target);
  std::vector<std::vector<uint8_t>> host;

  PipelineRun run;
  int n = dir ? dir->frames : gen->frames();
  if (opts.max_frames > 0) n = std::min(n, opts.max_frames);
  for (int f = 0; f < n; ++f) {
    Image grey;
    std::vector<uint8_t> uyvy;
    FrameInput in;
    in.index = f;
    if (dir) {
      grey = dir->grey(f);
      if (dir->has_uyvy) uyvy = dir->uyvy(f);
      in.truth = dir->truth[size_t(f)];
      in.camera = &dir->camera;
    } else {
      RenderResult rr = gen->render();
      grey = std::move(rr.grey);
      uyvy = std::move(rr.uyvy);
      in.truth = gen->truth();
      in.camera = &gen->camera();
    }
    in.grey = &grey;
    in.uyvy = uyvy.empty() ? nullptr : &uyvy;
    CheckCall cc = def.make_call(in, params);
    if (f == 0) params.check_all_used();

    FrameRecord rec;
    FrameOutput host_out;
    if (!on_target || opts.compare_host) {
      refresh_host_buffers(host, cc, f == 0);
      HostBuffers hb(host);
      cc.host(hb);
      host_out = def.decode(host);
    }
    if (on_target) {
      const Call call = target_call(cc, k.index, impl);
      CallResult r = session->call(call);
      std::string err = describe_failure(call, r, target->elf());
      if (!err.empty()) throw CallFailed(def.name + " frame " + std::to_string(f) + ": " + err);
      rec.out = def.decode(r.data);
      rec.cycles = r.cycles;
      if (opts.compare_host) {
        std::string d = compare_outputs(rec.out, host_out);
        if (!d.empty()) run.mismatches.push_back("frame " + std::to_string(f) + ": " + d);
      }
    } else {
      rec.out = host_out;
    }
    in.grey = nullptr;
    in.uyvy = nullptr;
    rec.in = in;
    run.frames.push_back(rec);
    if (opts.progress) std::fprintf(stderr, "\r  frame %d/%d", f + 1, n);

    if (gen && f + 1 < n) {
      if (opts.closed_loop) {
        const Drive d = rec.out.has_decision ? rec.out.decision : Drive::Stop;
        if (!gen->advance(gen->drive_step(d), true)) ++run.collisions;
      } else {
        gen->advance();
      }
    }
  }
  if (opts.progress) std::fprintf(stderr, "\r%*s\r", 30, "");
  if (!opts.closed_loop)
    for (const auto &r : run.frames) run.collisions += r.in.truth.collision;
  return run;
}

std::string pipeline_csv(const PipelineRun &run) {
  std::ostringstream o;
  o << "frame,cycles,fps_486MHz,fps_600MHz,decision,est_x_in,est_y_in,est_heading_deg,"
       "true_x_in,true_y_in,true_heading_deg,blocked,clearance_in,collision";
  if (!run.frames.empty())
    for (const auto &d : run.frames[0].out.diag) o << "," << d.first;
  o << "\n";
  char buf[64];
  auto fmt = [&](double v) {
    std::snprintf(buf, sizeof buf, "%.4f", v);
    return std::string(buf);
  };
  for (const auto &r : run.frames) {
    const auto &t = r.in.truth;
    o << r.in.index << "," << r.cycles << "," << (r.cycles ? fmt(kSrv1Hz / r.cycles) : "") << ","
      << (r.cycles ? fmt(kBf537MaxHz / r.cycles) : "") << ","
      << (r.out.has_decision ? drive_name(r.out.decision) : "") << ",";
    if (r.out.has_pose) o << fmt(r.out.x_in) << "," << fmt(r.out.y_in) << "," << fmt(r.out.heading_deg);
    else o << ",,";
    o << "," << fmt(t.pose.x_in) << "," << fmt(t.pose.y_in) << "," << fmt(t.pose.heading_deg) << ","
      << t.blocked << "," << (std::isfinite(t.clearance_in) ? fmt(t.clearance_in) : "inf") << "," << t.collision;
    for (const auto &d : r.out.diag) o << "," << d.second;
    o << "\n";
  }
  return o.str();
}

std::vector<std::string> pipeline_summary(const PipelineDef &def, const PipelineRun &run) {
  std::vector<std::string> lines;
  char b[256];
  const auto &fr = run.frames;
  if (fr.empty()) return {"no frames"};
  double sum = 0;
  uint32_t lo = UINT32_MAX, hi = 0;
  for (const auto &r : fr) sum += r.cycles, lo = std::min(lo, r.cycles), hi = std::max(hi, r.cycles);
  if (hi > 0) {
    const double mean = sum / double(fr.size());
    std::snprintf(b, sizeof b, "cycles per frame: mean %.0f, min %u, max %u", mean, lo, hi);
    lines.push_back(b);
    std::snprintf(b, sizeof b, "frame rate: %.1f frames/s at 486 MHz (SRV-1), %.1f at 600 MHz",
                  kSrv1Hz / mean, kBf537MaxHz / mean);
    lines.push_back(b);
  }
  if (fr[0].out.has_decision) {
    int counts[4] = {0, 0, 0, 0}, agree = 0, blocked = 0, turned_when_blocked = 0;
    for (const auto &r : fr) {
      ++counts[int(r.out.decision)];
      const bool go = r.out.decision == Drive::Forward;
      agree += go == !r.in.truth.blocked;
      if (r.in.truth.blocked) {
        ++blocked;
        turned_when_blocked += !go;
      }
    }
    std::snprintf(b, sizeof b, "decisions: forward %d, left %d, right %d, stop %d", counts[1], counts[2],
                  counts[3], counts[0]);
    lines.push_back(b);
    std::snprintf(b, sizeof b,
                  "against the truth: %.1f%% of frames go forward exactly when the path is clear; "
                  "turned in %d of %d blocked frames",
                  100.0 * agree / double(fr.size()), turned_when_blocked, blocked);
    lines.push_back(b);
  }
  std::snprintf(b, sizeof b, "collisions: %d", run.collisions);
  lines.push_back(b);
  if (fr.back().out.has_pose) {
    const auto &last = fr.back();
    const double ex = last.out.x_in - last.in.truth.pose.x_in, ey = last.out.y_in - last.in.truth.pose.y_in;
    std::snprintf(b, sizeof b, "final pose error: %.2f in, %.2f deg", std::hypot(ex, ey),
                  last.out.heading_deg - last.in.truth.pose.heading_deg);
    lines.push_back(b);
  }
  if (def.summarize)
    for (auto &l : def.summarize(fr)) lines.push_back(l);
  if (!run.mismatches.empty()) {
    std::snprintf(b, sizeof b, "host and Blackfin builds differ in %zu frames; first: %s",
                  run.mismatches.size(), run.mismatches[0].c_str());
    lines.push_back(b);
  }
  return lines;
}

namespace {

// The arena's static obstacles as outlines in their own colours, under the trajectory.
std::vector<Shape> arena_shapes(const World &w) {
  std::vector<Shape> out;
  for (const Obstacle &ob : w.obstacles) {
    if (ob.mover >= 0) continue;
    char fill[8];
    auto c = [](float v) { return int(std::lround(std::clamp(v, 0.0f, 255.0f))); };
    std::snprintf(fill, sizeof fill, "#%02x%02x%02x", c(ob.color.r), c(ob.color.g), c(ob.color.b));
    Shape sh{fill, {}, {}};
    if (ob.kind == ObstacleKind::Cylinder) {
      for (int k = 0; k < 32; ++k) {
        const double a = 2 * M_PI * k / 32;
        sh.x.push_back(ob.centre.x + ob.radius * std::cos(a));
        sh.y.push_back(ob.centre.y + ob.radius * std::sin(a));
      }
    } else {
      for (const Vec2 &v : ob.corners) sh.x.push_back(v.x), sh.y.push_back(v.y);
    }
    out.push_back(std::move(sh));
  }
  return out;
}

void write_svgs(const std::string &prefix, const std::string &name, const PipelineRun &run,
                const World *arena) {
  Series truth{"true path", "#1f77b4", {}, {}}, est{"estimated", "#d62728", {}, {}};
  Series cyc{"cycles per frame", "#2ca02c", {}, {}};
  for (const auto &r : run.frames) {
    truth.x.push_back(r.in.truth.pose.x_in);
    truth.y.push_back(r.in.truth.pose.y_in);
    if (r.out.has_pose) {
      est.x.push_back(r.out.x_in);
      est.y.push_back(r.out.y_in);
    }
    cyc.x.push_back(r.in.index);
    cyc.y.push_back(r.cycles);
  }
  std::vector<Series> path = {truth};
  if (!est.x.empty()) path.push_back(est);
  std::string t = svg_plot(name + ": trajectory", "x (in)", "y (in)", path, true,
                           arena ? arena_shapes(*arena) : std::vector<Shape>{});
  write_file_atomic(prefix + "-trajectory.svg", t.data(), t.size());
  std::string c = svg_plot(name + ": simulator cycles per frame", "frame", "cycles", {cyc}, false);
  write_file_atomic(prefix + "-cycles.svg", c.data(), c.size());
}

int pipeline_main(int argc, char **argv) {
  std::string scene, spec, csv, svg, elf;
  std::vector<std::string> name, param_list;
  PipelineRunOptions opts;
  bool quiet = false;
  std::string listed;
  for (const PipelineDef *p : pipelines()) {
    char line[256];
    std::snprintf(line, sizeof line, "  %-16s %s\n", p->name.c_str(), p->summary.c_str());
    listed += line;
  }
  CommandLine cl("pipeline");
  cl.about("Runs a vision pipeline frame by frame in the simulator on a scene directory (bfbench scene)\n"
           "or a generated scene (SPEC as for bfbench scene). Prints per frame the cycles, the frame\n"
           "rate at 486 MHz (the SRV-1) and 600 MHz, the decision or pose and the ground truth, then a\n"
           "summary. Exactly one of --scene and --spec.")
      .operands("NAME", &name, 1, 1, "(bfbench pipeline --help lists them)")
      .text("--scene", "DIR", &scene, "a scene directory (bfbench scene --out)")
      .text("--spec", "SPEC", &spec, "a scene generated as bfbench scene --spec would")
      .text("--impl", "asm|c|host", &opts.impl, "the build (default " + opts.impl + ")")
      .flag("--closed-loop", &opts.closed_loop, "the pipeline's decisions drive the robot (--spec only)")
      .integer("--frames", "N", 1, 1000000, &opts.max_frames, "at most N frames")
      .texts("--param", "K=V", &param_list, "a pipeline parameter")
      .text("--csv", "FILE", &csv, "write the frames as CSV")
      .text("--svg", "PREFIX", &svg, "write PREFIX-trajectory.svg and PREFIX-cycles.svg")
      .flag("--compare-host", &opts.compare_host, "also run the host build; fail (exit 1) on any difference")
      .flag("--quiet", &quiet, "the summary only")
      .text("--firmware", "ELF", &elf, "the firmware image (default this build's)")
      .tail("pipelines:\n" + listed);
  if (!cl.parse(argc, argv)) return kExitOk;
  if (opts.impl != "host") parse_impl(opts.impl);
  Params params;
  for (const auto &p : param_list) params.set(p);
  const PipelineDef *def = find_pipeline(name[0]);
  if (!def) throw UsageError("unknown pipeline '" + name[0] + "' (bfbench pipeline --help)");
  if (scene.empty() == spec.empty()) throw UsageError("give exactly one of --scene DIR and --spec SPEC");
  if (opts.closed_loop && spec.empty()) throw UsageError("--closed-loop needs --spec (a generated scene)");

  std::unique_ptr<SceneData> dir;
  std::unique_ptr<SceneGenerator> gen;
  if (!scene.empty()) dir = std::make_unique<SceneData>(read_scene(scene));
  else gen = std::make_unique<SceneGenerator>(parse_scene_spec(spec));
  std::unique_ptr<Target> target;
  if (opts.impl != "host" || opts.compare_host) {
    FirmwareImage fw = product_firmware();
    if (!elf.empty()) fw.elf = elf;
    target = std::make_unique<Target>(fw, default_simulator());
  }
  opts.progress = quiet && isatty(2);
  PipelineRun run = run_pipeline(*def, target.get(), dir.get(), gen.get(), params, opts);
  if (!quiet) {
    std::printf("%5s %10s %8s %8s %-8s %24s %24s %7s\n", "frame", "cycles", "fps@486", "fps@600",
                "decision", "estimated x,y,heading", "true x,y,heading", "blocked");
    for (const auto &r : run.frames) {
      char est[64] = "-", tru[64];
      if (r.out.has_pose)
        std::snprintf(est, sizeof est, "%.2f,%.2f,%.1f", r.out.x_in, r.out.y_in, r.out.heading_deg);
      std::snprintf(tru, sizeof tru, "%.2f,%.2f,%.1f", r.in.truth.pose.x_in, r.in.truth.pose.y_in,
                    r.in.truth.pose.heading_deg);
      std::printf("%5d %10u %8.1f %8.1f %-8s %24s %24s %7s\n", r.in.index, r.cycles,
                  r.cycles ? kSrv1Hz / r.cycles : 0.0, r.cycles ? kBf537MaxHz / r.cycles : 0.0,
                  r.out.has_decision ? drive_name(r.out.decision) : "-", est, tru,
                  r.in.truth.blocked ? "yes" : "no");
    }
  }
  std::printf("%s (%s%s), %zu frames:\n", def->name.c_str(), opts.impl.c_str(),
              opts.closed_loop ? ", closed loop" : "", run.frames.size());
  for (const auto &l : pipeline_summary(*def, run)) std::printf("  %s\n", l.c_str());
  if (!csv.empty()) {
    std::string c = pipeline_csv(run);
    write_file_atomic(csv, c.data(), c.size());
  }
  if (!svg.empty()) write_svgs(svg, def->name, run, dir ? &dir->arena : &gen->arena());
  return run.mismatches.empty() ? kExitOk : kExitFailed;
}

}  // namespace

int pipeline_command(int argc, char **argv) {
  return run_command("pipeline", [&] { return pipeline_main(argc, argv); });
}

}  // namespace bvb
