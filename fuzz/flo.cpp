// Middlebury .flo: parse_flo, what read_flo runs on a file's bytes.
#include "fuzz_target.h"

using namespace bvb;

BVB_FUZZ_TARGET {
  const auto f = fuzz::parse_or_reject([&] { return parse_flo(fuzz::bytes_of(data, size), "fuzz.flo"); });
  if (!f) return 0;
  const size_t n = size_t(f->width) * f->height;
  if (f->width < 1 || f->height < 1 || f->width > kMaxFrameDim || f->height > kMaxFrameDim ||
      f->u.size() != n || f->v.size() != n || size != 12 + 8 * n)
    fuzz::finding("parse_flo returned a field outside its limits");
  return 0;
}
