// The benches' camera frames: the boxes arena seen from its start, looking at the red box, and
// half an inch further on, rendered once by `bfbench scene` at 160x120 and 320x240 and kept in
// the repository (frames/scenes/bench_boxes_WxH; each scene.txt gives the spec that made it).
// Their files are checked against their SHA256SUMS when loaded, and other sizes are made from
// the 320x240 frames by integer resampling, so that a bench's input, and so its exact budget, is
// the same bytes on every host (the renderer computes in floating point through libm).
#pragma once

#include <string>
#include <vector>

#include "image.h"
#include "scene/camera.h"
#include "scene/scene_io.h"

namespace bvb {

struct BenchScene {
  Camera camera;                   // the stored camera, or Camera::standard(w, h) when resampled
  std::vector<Image> grey;         // [frame]
  std::vector<FrameTruth> truth;   // [frame], as stored (poses and wheel ticks)
};

// The bench scene at w x h (cached). Throws InputError when a file is missing or its bytes are
// not the ones SHA256SUMS names.
const BenchScene &bench_scene(int w, int h);
// The stored scene at w x h, or "" when that size is not stored.
std::string bench_scene_dir(int w, int h);

// Verifies every file `dir`/SHA256SUMS lists (lines "<64 hex digits>  <name>", as sha256sum
// writes them) and that `required` are among them; throws InputError naming the first problem.
void verify_sha256sums(const std::string &dir, const std::vector<std::string> &required);

// Integer resampling of a grey image: each output pixel the rounded mean of the source pixels
// its footprint covers when shrinking, bilinear with 1/256 weights when growing (per axis).
Image resample_grey(const Image &src, int w, int h);

}  // namespace bvb
