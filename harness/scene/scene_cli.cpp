#include "scene_cli.h"

#include <cstdio>
#include <exception>
#include <string>

#include "io.h"
#include "scene_io.h"
#include "world.h"
#include "simdriver.h"

namespace bvb {

namespace {

const char *kUsage =
    "usage: scene --spec SPEC --out DIR [--force]   render a scene into DIR\n"
    "       scene --check DIR                      read DIR back and summarise it\n"
    "       scene --list-arenas                    the bundled arenas\n"
    "       scene --help\n"
    "SPEC is comma-separated key=value, e.g. arena=boxes,path=square,size=160x120,frames=200,"
    "seed=7,noise=2\n"
    "keys: arena path length angle side dir size frames seed noise speed turn_rate fx cam_height\n"
    "      tilt cam_offset ss mover flicker flicker_period light_step step_gain step_offset slip\n"
    "      enc_noise tpi wheelbase radius block_dist start texture_seed uyvy flow rgb\n"
    "      (meanings and defaults: harness/scene/scene_io.h)\n"
    "DIR gets frame_NNNN.pgm/.uyvy, flow_NNNN.flo, truth.csv, columns.csv, scene.txt, arena.txt;\n"
    "it is written under a temporary name, read back and renamed when complete. --force\n"
    "replaces an existing scene directory that holds only what a scene writes (anything else\n"
    "in it is refused, never deleted).\n"
    "Units: inches and degrees; heading counter-clockwise from +x; image x right, y down.\n";

int usage_error(const std::string &msg) {
  std::fprintf(stderr, "scene: %s (try --help)\n", sim::printable(msg, 2000).c_str());
  return 2;
}

}  // namespace

int scene_command(int argc, char **argv) {
  std::string spec, out, check;
  bool have_spec = false, force = false, list = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](std::string &dst) {
      if (i + 1 >= argc) return false;
      dst = argv[++i];
      return true;
    };
    if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      std::fputs("what each key accepts:\n", stdout);
      std::fputs(scene_spec_ranges().c_str(), stdout);
      return 0;
    } else if (a == "--spec") {
      if (!value(spec)) return usage_error("--spec needs a value");
      have_spec = true;
    } else if (a == "--out") {
      if (!value(out)) return usage_error("--out needs a directory");
    } else if (a == "--check") {
      if (!value(check)) return usage_error("--check needs a directory");
    } else if (a == "--force") {
      force = true;
    } else if (a == "--list-arenas") {
      list = true;
    } else {
      return usage_error("unknown argument '" + a + "'");
    }
  }
  try {
    if (list) {
      if (have_spec || !out.empty() || !check.empty()) return usage_error("--list-arenas takes no other options");
      const auto names = list_arenas();
      if (names.empty()) throw InputError("no arenas found (set BVB_ARENA_DIR to frames/arenas)");
      for (const auto &n : names) std::printf("%s\n", n.c_str());
      return 0;
    }
    if (!check.empty()) {
      if (have_spec || !out.empty()) return usage_error("--check takes no --spec or --out");
      const SceneData d = read_scene(check);
      int blocked = 0;
      for (const auto &t : d.truth) blocked += t.blocked;
      std::printf("%s: %d frames %dx%d, arena %s, %d blocked, files pgm%s%s%s\n", check.c_str(),
                  d.frames, d.camera.width, d.camera.height, d.arena.name.c_str(), blocked,
                  d.has_uyvy ? " uyvy" : "", d.has_rgb ? " ppm" : "", d.has_flow ? " flo" : "");
      return 0;
    }
    if (!have_spec) return usage_error("--spec is required");
    if (out.empty()) return usage_error("--out is required");
    const SceneSpec parsed = parse_scene_spec(spec);
    write_scene(parsed, out, force);
    const SceneData d = read_scene(out);
    std::printf("%s: %d frames %dx%d, arena %s\n", out.c_str(), d.frames, d.camera.width,
                d.camera.height, d.arena.name.c_str());
    return 0;
  } catch (const InputError &e) {
    std::fprintf(stderr, "scene: %s\n", sim::printable(e.what(), 2000).c_str());
    return 2;
  } catch (const std::exception &e) {
    // Exit 1 means a check failed; a fault of the program is reported as bfbench's main does.
    std::fprintf(stderr, "scene: internal error: %s\n", sim::printable(e.what(), 2000).c_str());
    return 2;
  }
}

}  // namespace bvb
