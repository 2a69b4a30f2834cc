// SHA-256 (FIPS 180-4), for checking that files the budgets depend on are the bytes they were
// measured on (frames/scenes/bench_boxes_*/SHA256SUMS, in the format `sha256sum -c` reads).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace bvb {

// The digest of `n` bytes at `data` as 64 lower-case hex digits.
std::string sha256_hex(const uint8_t *data, size_t n);
inline std::string sha256_hex(const std::string &s) {
  return sha256_hex(reinterpret_cast<const uint8_t *>(s.data()), s.size());
}

}  // namespace bvb
