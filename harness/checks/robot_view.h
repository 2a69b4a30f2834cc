// What the robot's camera sees: the boxes arena (frames/arenas/boxes.txt) rendered by the scene
// generator from a few fixed poses, at any size. Checks and benches of the segmentation kernels
// use it for realistic frames (a textured floor, coloured boxes, walls) that need no files
// outside the repository.
#pragma once

#include <map>
#include <tuple>

#include "scene/render.h"
#include "scene/world.h"

namespace bvb {

// Pose 0 is the arena's start: the red box straight ahead, the blue one to the left. The others
// look across the room from elsewhere. Results are cached per size and pose.
inline const RenderResult &robot_view(int w, int h, int pose = 0) {
  static std::map<std::tuple<int, int, int>, RenderResult> cache;
  auto key = std::make_tuple(w, h, pose);
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  static const World world = load_arena("boxes");
  static const Pose poses[] = {{24, 30, 0}, {60, 30, 60}, {30, 80, -30}, {70, 70, 135}};
  RenderOptions opt;
  opt.supersample = 2;
  opt.noise_sigma = 1.5;
  opt.noise_seed = uint64_t(pose) + 1;
  return cache[key] = render(world, poses[pose & 3], Camera::standard(w, h), opt);
}

}  // namespace bvb
