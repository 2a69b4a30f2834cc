// NumPy .npy: parse_npy, what read_image runs on a .npy file's bytes.
#include "formats.h"
#include "fuzz_target.h"

using namespace bvb;

BVB_FUZZ_TARGET {
  const auto a = fuzz::parse_or_reject([&] { return parse_npy(fuzz::bytes_of(data, size), "fuzz.npy"); });
  if (!a) return 0;
  size_t n = 1;
  for (size_t d : a->shape) n *= d;
  const size_t elem = a->dtype.empty() ? 0 : size_t(a->dtype.back() - '0');
  if (elem != 1 && elem != 2 && elem != 4) fuzz::finding("parse_npy returned an unknown element size");
  if (a->data.size() != n * elem) fuzz::finding("parse_npy's data does not match its shape");
  // What bfbench writes must read back as the same array.
  const auto back = fuzz::parse_or_reject([&] { return parse_npy(encode_npy(*a), "round trip"); });
  if (!back) fuzz::finding("encode_npy wrote a file parse_npy rejects");
  if (back->dtype != a->dtype || back->shape != a->shape || back->data != a->data)
    fuzz::finding("encode_npy then parse_npy changed the array");
  return 0;
}
