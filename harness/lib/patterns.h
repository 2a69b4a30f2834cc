// Inputs for checks: crafted 8-bit patterns that hit edge values and data-dependent paths,
// seeded noise, crops of real frames, and the frame sizes every kernel is checked at.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "check.h"
#include "image.h"

namespace bvb {

enum class Pattern {
  Zero, Max, Checker, RampX, RampY, Impulse, Edges, Noise, Runs, Real
};
const std::vector<Pattern> &all_patterns();
const char *pattern_name(Pattern p);

// A width x height 8-bit plane with `stride` bytes per row; bytes in the row padding are noise
// too, so a kernel that reads them shows it.
std::vector<uint8_t> make_plane(Pattern p, int width, int height, int stride, Rng &rng,
                                const std::string &frames_real);

struct Size {
  int w, h;
};
// Sizes to check a kernel whose smallest legal frame is min_w x min_h: the smallest, one more
// in each direction, odd and even small sizes, the SRV-1's 160x120, a few seeded random ones;
// a campaign adds 320x240, 640x480 and more random sizes.
std::vector<Size> check_sizes(int min_w, int min_h, Rng &rng, bool campaign);

// A row stride for width w: usually w, sometimes padded (strides are part of every contract).
int pick_stride(int w, Rng &rng, int multiple = 1);

// Grey crop of a real frame (a Middlebury or Yosemite image under frames_real), size w x h,
// position chosen by rng; empty when the frames are not there.
Image real_crop(const std::string &frames_real, int w, int h, Rng &rng);
// The frames-real directory: $BFBENCH_FRAMES_REAL, else the build-time default.
std::string default_frames_real();

}  // namespace bvb
