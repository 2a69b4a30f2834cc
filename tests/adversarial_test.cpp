// The adversarial call, without a simulator: what Checker::add does to every call (random
// poison, junk seeds, buffers moved to the end of SDRAM), the canaries' seed per check seed,
// and the words the failures say (ABI bits, faults near a buffer). The firmware's side is proved
// by the self-test's broken twins (tests/sim/selftest_test.cpp).
#include <gtest/gtest.h>

#include <set>

#include "generate.h"
#include "patterns.h"

namespace bvb {
namespace {

using testing_gen::generation_target;

std::vector<CheckCall> calls_of(const std::string &kernel, uint32_t seed, const Target &t) {
  CheckOptions o;
  o.seed = seed;
  o.frames_real = default_frames_real();
  Checker ck(t, o);
  const Family *f = family_of(kernel);
  EXPECT_NE(f, nullptr);
  ck.reseed(f->name);
  f->check(ck);
  std::vector<CheckCall> out;
  for (const CheckCall *c : ck.pending()) out.push_back(*c);
  return out;
}

// The probe: every output started as poison_byte(i), the same bytes for every seed and call.
TEST(Adversarial, OutputsStartAsRandomBytesThatDifferPerCall) {
  const Target t = generation_target();
  std::set<std::vector<uint8_t>> heads;
  size_t outputs = 0, fixed = 0;
  for (uint32_t seed : {1u, 2u})
    for (const CheckCall &c : calls_of("add_sat_u8", seed, t))
      for (const Buffer &b : c.bufs) {
        if (b.role != Role::Out || b.data.size() < 8) continue;
        ++outputs;
        bool is_fixed = true;
        for (size_t i = 0; i < b.data.size(); ++i) is_fixed &= b.data[i] == poison_byte(i);
        fixed += is_fixed;
        heads.insert(std::vector<uint8_t>(b.data.begin(), b.data.begin() + 8));
      }
  ASSERT_GT(outputs, 20u);
  EXPECT_EQ(fixed, 0u) << "outputs still start as the fixed poison pattern";
  EXPECT_EQ(heads.size(), outputs) << "two calls' outputs started with the same bytes";
}

TEST(Adversarial, EveryCallHasItsOwnJunkSeed) {
  const Target t = generation_target();
  std::set<uint32_t> seeds;
  const auto calls = calls_of("add_sat_u8", 5, t);
  for (const CheckCall &c : calls) {
    EXPECT_NE(c.junk_seed, 0u) << c.case_id << ": no junk";
    seeds.insert(c.junk_seed);
  }
  EXPECT_EQ(seeds.size(), calls.size());
}

// About half the calls with a buffer in SDRAM end one there, an input where there is one.
TEST(Adversarial, HalfTheCallsEndABufferAtTheEndOfSdram) {
  const Target t = generation_target();
  size_t with_sdram = 0, at_end = 0, input_at_end = 0;
  for (uint32_t seed : {1u, 2u, 3u})
    for (const CheckCall &c : calls_of("add_sat_u8", seed, t)) {
      size_t n_end = 0, sdram = 0;
      for (const Buffer &b : c.bufs) {
        sdram += b.place == BVB_PLACE_SDRAM || b.place == BVB_PLACE_SDRAM_END;
        if (b.place != BVB_PLACE_SDRAM_END) continue;
        ++n_end;
        input_at_end += b.role == Role::In;
        EXPECT_NE(c.case_name.find("'" + b.name + "' at SDRAM end"), std::string::npos) << c.case_name;
      }
      EXPECT_LE(n_end, 1u) << c.case_id;
      with_sdram += sdram > 0;
      at_end += n_end;
    }
  ASSERT_GT(with_sdram, 30u);
  EXPECT_GT(at_end, with_sdram / 4);
  EXPECT_LT(at_end, with_sdram * 3 / 4);
  EXPECT_EQ(input_at_end, at_end) << "add_sat_u8 has inputs in SDRAM whenever it has SDRAM buffers";
}

TEST(Adversarial, CanariesDifferPerSeed) {
  std::set<uint32_t> s;
  for (uint32_t seed = 0; seed < 100; ++seed) {
    EXPECT_EQ(canary_seed_of(seed) & 1, 1u);
    s.insert(canary_seed_of(seed));
  }
  EXPECT_EQ(s.size(), 100u);
}

TEST(Adversarial, AbiBitsSayWhatWasBroken) {
  EXPECT_EQ(abi_names(BVB_ABI_R4 | BVB_ABI_P5), "did not preserve R4, P5");
  EXPECT_NE(abi_names(BVB_ABI_L3).find("left L3 non-zero (circular addressing"), std::string::npos);
  EXPECT_NE(abi_names(BVB_ABI_LOOP1).find("left hardware loop 1 armed (LC1 non-zero"), std::string::npos);
  EXPECT_NE(abi_names(BVB_ABI_LOOP0 | BVB_ABI_LOOP1).find("loop 0 and 1 armed (LC0 and LC1"), std::string::npos);
}

// A data CPLB miss just past the end of a buffer placed at the end of SDRAM names the buffer.
TEST(Adversarial, AFaultPastABufferNamesIt) {
  Call c;
  Buffer a, b;
  a.name = "a";
  a.data.resize(100);
  b.name = "b";
  b.data.resize(100);
  b.place = BVB_PLACE_SDRAM_END;
  c.bufs = {a, b};
  CallResult r;
  r.status = BVB_FAULT;
  r.seqstat = 0x26;  // data access CPLB miss
  r.buf_addr[0] = 0x1000;
  r.buf_addr[1] = 0x02000000 - 100;
  r.addr = 0x02000000;
  EXPECT_EQ(fault_near_buffer(c, r),
            "an access 1 byte past the end of buffer 'b' (byte offset 100 of 100); it ended at the end of "
            "SDRAM, where nothing is mapped");
  r.addr = 0x1000 - 8;
  EXPECT_EQ(fault_near_buffer(c, r), "an access 8 bytes before the start of buffer 'a'");
  r.addr = 0x00800000;  // near no buffer
  EXPECT_EQ(fault_near_buffer(c, r), "");
  r.addr = 0x02000000;
  r.seqstat = 0x21;  // undefined instruction: the address means nothing
  EXPECT_EQ(fault_near_buffer(c, r), "");
}

}  // namespace
}  // namespace bvb
