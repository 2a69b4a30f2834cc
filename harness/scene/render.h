// Ray-cast renderer of what the robot's camera sees, and the per-frame ground truth that comes
// from the same geometry: column free-space distances, dense optical flow. Units, axes and the
// camera model: camera.h; the arena: world.h.
//
// Rendering: one ray through each pixel centre gives colour, surface and depth; pixels whose
// surface (floor, an obstacle face, nothing) differs from a 4-neighbour's are re-rendered as the
// mean of supersample x supersample rays on a regular sub-pixel grid (anti-aliased edges).
// Textures are mip-mapped (trilinear) by the ray's footprint, so flat areas do not alias.
// Everything is deterministic: the same inputs give the same bytes.
//
// Colour pipeline, per pixel: linear RGB 0..255 (surface colour x (1 + contrast x texture) x
// lighting) -> gain * c + offset -> + N(0, noise_sigma^2) per channel -> round half up, clamp to
// 0..255 = `rgb`. Then BT.601 studio-range integer conversion (the classic 8-bit form):
//   Y = ((66 R + 129 G + 25 B + 128) >> 8) + 16          (16..235)
//   U = ((-38 R - 74 G + 112 B + 128) >> 8) + 128        (16..240)
//   V = ((112 R - 94 G - 18 B + 128) >> 8) + 128         (16..240)
// with >> an arithmetic (flooring) shift. `grey` is exactly the Y plane; `uyvy` holds U Y0 V Y1
// per pixel pair, U and V the rounded-up mean of the two pixels' values ((a + b + 1) >> 1).
#pragma once

#include <cstdint>
#include <vector>

#include "camera.h"
#include "image.h"
#include "world.h"

namespace bvb {

struct RenderOptions {
  int supersample = 3;         // rays per axis at geometric edges; 1 = centre ray only
  double gain = 1.0;           // global lighting change: gain * c + offset, per RGB channel
  double offset = 0.0;
  double noise_sigma = 0.0;    // sensor noise: Gaussian, per RGB channel, in 0..255 levels
  uint64_t noise_seed = 0;     // the noise field is a function of this seed only
};

// Surface ids in RenderResult::surface: an index into world.obstacles, or one of these.
constexpr int16_t kSurfaceFloor = -1;
constexpr int16_t kSurfaceNone = -2;  // the ray hits nothing (open arena: background colour)

struct RenderResult {
  Image rgb;                     // 3 channels
  Image grey;                    // 1 channel: the Y of BT.601 above
  std::vector<uint8_t> uyvy;     // width * height * 2 bytes; empty when width is odd
  std::vector<float> depth;      // camera-frame Z (inches) at each pixel centre; +inf: nothing
  std::vector<int16_t> surface;  // what each pixel centre sees
};

// Renders `world` as it is (pass world_at_frame(...) to include the movers).
RenderResult render(const World &world, const Pose &pose, const Camera &cam,
                    const RenderOptions &opt = {});

void rgb_to_yuv(int r, int g, int b, int &y, int &u, int &v);
Image rgb_to_grey(const Image &rgb);                // the Y plane
std::vector<uint8_t> rgb_to_uyvy(const Image &rgb); // width must be even

// Per image column x (pixel-centre rays at x, continuous in y): where the visible floor ends.
// boundary_row[x]: the lowest row (largest y) whose centre does not see the floor, i.e. the floor
//   fills rows boundary_row+1 .. height-1; -1 when every row of the column sees floor (the
//   obstacle is above the top of the image); height-1 when the bottom row already does not.
// distance_in[x]: horizontal distance from the camera's foot (the floor point below the optical
//   centre) to the last visible floor point before the obstacle along that column, found to
//   1e-6 px by bisection, even when it lies above or below the image; +inf when the floor runs
//   to the horizon with nothing on it.
struct ColumnTruth {
  std::vector<double> distance_in;
  std::vector<int> boundary_row;
};
ColumnTruth column_truth(const World &world, const Pose &pose, const Camera &cam);

// Dense flow from frame a to frame b at a's pixel centres (u right, v down, pixels):
// the 3-D point each pixel sees, moved with its surface (static, or the mover's displacement
// between the two worlds), projected with b's pose. Points that hit nothing count as infinitely
// far (rotation only). Unknown (> 1e9): points behind b's camera, and points hidden in frame b
// (their depth in b exceeds the depth b rendered at all four pixels around their new position
// by more than 1% + 0.05 in). Points that leave the image keep their flow.
// wa and wb are the frame worlds (world_at_frame) that ra and rb were rendered from.
FlowField true_flow(const World &wa, const Pose &pa, const RenderResult &ra, const World &wb,
                    const Pose &pb, const RenderResult &rb, const Camera &cam);

}  // namespace bvb
