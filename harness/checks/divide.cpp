// Check for bvb/divide.h: the Blackfin build's integer division (the runtime's ___udivsi3 and
// libgcc's helpers on it) against the host's, on the pairs where a short-cut division goes
// wrong: quotients of every bit length (the helper runs one step per quotient bit), 0 and 1,
// a divisor above the dividend, equal values, the top bit set on either side, powers of two
// and their neighbours, and signed pairs of every sign. No bench: the pipelines' cycles are its
// measure (bfbench bench -k pipe_odometry).
#include "bvb/divide.h"

#include <cstdint>

#include "family.h"
#include "names.h"

namespace bvb {
namespace {

CheckCall divide_call(const std::vector<uint32_t> &num, const std::vector<uint32_t> &den, const std::string &name) {
  CheckCall c;
  c.kernel = "divide";
  c.case_name = name;
  const int n = int(num.size());
  c.pixels = n;
  int in = c.in("num", as_bytes(num), View{4, false, n, 1, n});
  int id = c.in("den", as_bytes(den), View{4, false, n, 1, n});
  int io = c.out("out", size_t(6) * std::max(n, 1) * 4, View{4, false, 6, std::max(n, 1), 6});
  c.buf(in).buf(id).buf(io).word(n);
  c.host = [=](HostBuffers &m) { bvb_divide_c(m.u32(in), m.u32(id), m.u32(io), n); };
  return c;
}

// A value of exactly `bits` significant bits (0: zero).
uint32_t of_bits(int bits, Rng &rng) {
  if (bits == 0) return 0;
  const uint32_t top = uint32_t(1) << (bits - 1);
  return top | (rng.u32() & (top - 1));
}

// Signed division is defined unless the divisor is 0 or the pair is INT32_MIN / -1.
bool defined(uint32_t n, uint32_t d) { return d != 0 && !(n == 0x80000000u && d == 0xFFFFFFFFu); }

void check(Checker &ck) {
  if (!ck.wants("divide")) return;
  Rng &rng = ck.rng();
  std::vector<uint32_t> num, den;
  auto add = [&](uint32_t n, uint32_t d) {
    if (!defined(n, d)) return;
    num.push_back(n);
    den.push_back(d);
  };
  // Edge values crossed with each other.
  std::vector<uint32_t> edge = {0, 1, 2, 3, 7, 8, 9, 255, 256, 65535, 65536, 65537, 0x7FFFFFFEu, 0x7FFFFFFFu,
                                0x80000000u, 0x80000001u, 0xFFFFFFFEu, 0xFFFFFFFFu};
  for (int b = 4; b < 32; b += 5) edge.push_back(uint32_t(1) << b), edge.push_back((uint32_t(1) << b) - 1);
  for (uint32_t n : edge)
    for (uint32_t d : edge) add(n, d);
  ck.add(divide_call(num, den, "edges " + std::to_string(num.size()) + " pairs"));
  // Every pair of bit lengths, a few times each: quotients of 0 to 32 bits.
  num.clear();
  den.clear();
  for (int nb = 0; nb <= 32; ++nb)
    for (int db = 1; db <= 32; ++db)
      for (int k = 0; k < 2; ++k) add(of_bits(nb, rng), of_bits(db, rng));
  ck.add(divide_call(num, den, "bit lengths " + std::to_string(num.size()) + " pairs"));
  // Random words, and counts 0 to 3 (the loop's ends), placed anywhere.
  for (int count : {0, 1, 2, 3, 64, 500}) {
    num.clear();
    den.clear();
    while (int(num.size()) < count) add(rng.u32() >> rng.uniform(0, 31), rng.u32() >> rng.uniform(0, 31));
    CheckCall c = divide_call(num, den, "random " + std::to_string(count) + " pairs");
    ck.place_randomly(c);
    ck.add(std::move(c));
  }
}

const Family kDivide{"divide", {"divide"}, check, nullptr, nullptr, nullptr};
BVB_FAMILY(kDivide);

}  // namespace
}  // namespace bvb
