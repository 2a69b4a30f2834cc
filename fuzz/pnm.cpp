// PGM/PPM, ASCII (P2/P3) and binary (P5/P6): parse_pnm, what read_pnm runs on a file's bytes.
#include "fuzz_target.h"

using namespace bvb;

BVB_FUZZ_TARGET {
  const auto img = fuzz::parse_or_reject([&] { return parse_pnm(fuzz::bytes_of(data, size), "fuzz.pnm"); });
  if (!img) return 0;
  if (img->width < 1 || img->height < 1 || img->width > kMaxFrameDim || img->height > kMaxFrameDim ||
      (img->channels != 1 && img->channels != 3) ||
      img->data.size() != size_t(img->width) * img->height * img->channels)
    fuzz::finding("parse_pnm returned an image outside its limits");
  // What bfbench writes must read back as the same image (the writer always emits maxval 255).
  const auto back = fuzz::parse_or_reject([&] { return parse_pnm(encode_pnm(*img), "round trip"); });
  if (!back) fuzz::finding("encode_pnm wrote a file parse_pnm rejects");
  if (back->width != img->width || back->height != img->height || back->channels != img->channels ||
      back->data != img->data)
    fuzz::finding("encode_pnm then parse_pnm changed the image");
  return 0;
}
