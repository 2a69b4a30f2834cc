// Raw UYVY: parse_uyvy, with the size bfbench gets from --size WxH taken from the input's first
// four bytes (width, height: 16-bit little-endian), and the frame then converted by the C
// references bfbench runs on it, in buffers of exactly their size so ASan sees any overrun.
#include <cstring>

#include "bvb/yuv.h"
#include "fuzz_target.h"

using namespace bvb;

BVB_FUZZ_TARGET {
  if (size < 4) return 0;
  const int w = data[0] | data[1] << 8, h = data[2] | data[3] << 8;
  const auto frame = fuzz::parse_or_reject([&] { return parse_uyvy(fuzz::bytes_of(data + 4, size - 4), "fuzz.uyvy", w, h); });
  if (!frame) return 0;
  if (frame->size() != size_t(w) * h * 2) fuzz::finding("parse_uyvy accepted a frame of the wrong size");
  std::vector<uint8_t> grey(size_t(w) * h), rgb(size_t(w) * h * 3);
  std::vector<uint8_t> scratch(BVB_UYVY_TO_GREY_SCRATCH_BYTES(w));
  bvb_uyvy_to_grey_c(frame->data(), grey.data(), w, h, 2 * w, w, scratch.data());
  bvb_uyvy_to_rgb24_c(frame->data(), rgb.data(), w, h, 2 * w, 3 * w);
  // Grey is documented as the Y bytes unchanged (bvb/yuv.h): every odd byte of the frame.
  for (size_t i = 0; i < grey.size(); ++i)
    if (grey[i] != (*frame)[2 * i + 1]) fuzz::finding("uyvy_to_grey changed a Y byte");
  return 0;
}
