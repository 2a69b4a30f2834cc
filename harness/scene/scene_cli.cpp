#include "scene_cli.h"

#include <cstdio>
#include <string>

#include "io.h"
#include "options.h"
#include "registry.h"
#include "scene_io.h"
#include "world.h"
#include "simdriver.h"

namespace bvb {

namespace {

int scene_main(int argc, char **argv) {
  std::string spec, out, check;
  bool force = false, list = false;
  CommandLine cl("scene");
  cl.forms({"--spec SPEC --out DIR [--force]   render a scene into DIR",
            "--check DIR                      read DIR back and summarise it",
            "--list-arenas                    the bundled arenas"})
      .about("SPEC is comma-separated key=value, e.g. arena=boxes,path=square,size=160x120,frames=200,"
             "seed=7,noise=2\n"
             "keys: arena path length angle side dir size frames seed noise speed turn_rate fx cam_height\n"
             "      tilt cam_offset ss mover flicker flicker_period light_step step_gain step_offset slip\n"
             "      enc_noise tpi wheelbase radius block_dist start texture_seed uyvy flow rgb\n"
             "      (meanings and defaults: harness/scene/scene_io.h)\n"
             "DIR gets frame_NNNN.pgm/.uyvy, flow_NNNN.flo, truth.csv, columns.csv, scene.txt, arena.txt;\n"
             "it is written under a temporary name, read back and renamed when complete.\n"
             "Units: inches and degrees; heading counter-clockwise from +x; image x right, y down.")
      .text("--spec", "SPEC", &spec, "the scene to render")
      .text("--out", "DIR", &out, "where to write it")
      .flag("--force",  &force,
            "replace an existing scene directory that holds only what a scene writes (anything else in it is "
            "refused, never deleted)")
      .text("--check", "DIR", &check, "read a scene back and summarise it")
      .flag("--list-arenas", &list, "the bundled arenas")
      .tail("what each key accepts:\n" + scene_spec_ranges());
  if (!cl.parse(argc, argv)) return kExitOk;
  const bool have_spec = cl.given("--spec");
  if (list) {
    if (have_spec || cl.given("--out") || cl.given("--check")) throw UsageError("--list-arenas takes no other options");
    const auto names = list_arenas();
    if (names.empty()) throw InputError("no arenas found (set BVB_ARENA_DIR to frames/arenas)");
    for (const auto &n : names) std::printf("%s\n", n.c_str());
    return kExitOk;
  }
  if (cl.given("--check")) {
    if (have_spec || cl.given("--out")) throw UsageError("--check takes no --spec or --out");
    const SceneData d = read_scene(check);
    int blocked = 0;
    for (const auto &t : d.truth) blocked += t.blocked;
    std::printf("%s: %d frames %s, arena %s, %d blocked, files pgm%s%s%s\n", check.c_str(), d.frames,
                size_name(d.camera.width, d.camera.height).c_str(), d.arena.name.c_str(), blocked,
                d.has_uyvy ? " uyvy" : "", d.has_rgb ? " ppm" : "", d.has_flow ? " flo" : "");
    return kExitOk;
  }
  if (!have_spec) throw UsageError("--spec is required (" + bfbench_name() + " scene --help)");
  if (!cl.given("--out")) throw UsageError("--out is required");
  const SceneSpec parsed = parse_scene_spec(spec);
  write_scene(parsed, out, force);
  const SceneData d = read_scene(out);
  std::printf("%s: %d frames %s, arena %s\n", out.c_str(), d.frames, size_name(d.camera.width, d.camera.height).c_str(),
              d.arena.name.c_str());
  return kExitOk;
}

}  // namespace

int scene_command(int argc, char **argv) {
  return run_command("scene", [&] { return scene_main(argc, argv); });
}

}  // namespace bvb
