// Inputs for checks: crafted 8-bit patterns that hit edge values and data-dependent paths,
// seeded noise, crops of real frames, and the frame sizes every kernel is checked at.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "check.h"
#include "image.h"
#include "names.h"

namespace bvb {

enum class Pattern {
  Zero, Max, Checker, RampX, RampY, Impulse, Edges, Noise, Runs, Real
};
const std::vector<Pattern> &all_patterns();
const char *pattern_name(Pattern p);

// A width x height 8-bit plane with `stride` bytes per row; bytes in the row padding are noise
// too, so a kernel that reads them shows it. Pattern::Real needs the frames (frames_real_present):
// without them it throws std::logic_error rather than hand back something else under the name
// "real" (a check asks Checker::patterns(), which leaves Real out then).
std::vector<uint8_t> make_plane(Pattern p, int width, int height, int stride, Rng &rng,
                                const std::string &frames_real);

// Sizes to check a kernel whose smallest legal frame is min_w x min_h: the smallest, one more
// in each direction, odd and even small sizes, the SRV-1's 160x120, a few seeded random ones;
// a campaign adds 320x240, 640x480 and more random sizes.
std::vector<Size> check_sizes(int min_w, int min_h, Rng &rng, bool campaign);

// A row stride for width w: usually w, sometimes padded (strides are part of every contract).
int pick_stride(int w, Rng &rng, int multiple = 1);

// Grey crop of a real frame (a Middlebury or Yosemite image under frames_real), size w x h,
// position chosen by rng; empty when the frames are not there. It takes one value of rng
// whether or not they are.
Image real_crop(const std::string &frames_real, int w, int h, Rng &rng);
// The frames-real directory: $BFBENCH_FRAMES_REAL, else the build-time default.
std::string default_frames_real();
// Whether the grey frames real_crop reads are all under dir.
bool frames_real_present(const std::string &dir);
// BVB_REQUIRE_FRAMES=1: a missing frames-real is an error, not a reason to skip (CI sets it).
bool frames_required();
// The one line said when real-frame cases are skipped (or, when required, the error).
std::string frames_missing_message(const std::string &dir);

// A textured grey image made by integer arithmetic only (the same bytes on every host and
// compiler): value noise of four octaves (cells of 32, 16, 8 and 4 pixels) sampled at
// (x * 256 + dx_q8, y * 256 + dy_q8) in 1/256 pixel, so that two calls with different offsets are
// the same texture moved by a sub-pixel amount. Budgeted bench inputs are made with it.
Image hermetic_texture(int w, int h, uint64_t seed, int32_t dx_q8 = 0, int32_t dy_q8 = 0);
// The texture at one point (1/256 pixel), for warps other than a translation.
uint8_t hermetic_texture_at(int64_t x_q8, int64_t y_q8, uint64_t seed);

}  // namespace bvb
