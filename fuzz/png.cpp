// PNG (8-bit grey or RGB through libpng): parse_png, what read_image runs on a .png file's bytes.
#include "formats.h"
#include "fuzz_target.h"

using namespace bvb;

BVB_FUZZ_TARGET {
  const auto img = fuzz::parse_or_reject([&] { return parse_png(fuzz::bytes_of(data, size), "fuzz.png"); });
  if (!img) return 0;
  if (img->width < 1 || img->height < 1 || img->width > kMaxFrameDim || img->height > kMaxFrameDim ||
      (img->channels != 1 && img->channels != 3) ||
      img->data.size() != size_t(img->width) * img->height * img->channels)
    fuzz::finding("parse_png returned an image outside its limits");
  // What bfbench writes must read back as the same image.
  const auto back = fuzz::parse_or_reject([&] { return parse_png(encode_png(*img, "round trip"), "round trip"); });
  if (!back) fuzz::finding("encode_png wrote a file parse_png rejects");
  if (back->width != img->width || back->height != img->height || back->channels != img->channels ||
      back->data != img->data)
    fuzz::finding("encode_png then parse_png changed the image");
  return 0;
}
