// A serving session runs many calls in one simulator process; persistent buffers keep what the
// previous call left in the window.
#include <gtest/gtest.h>

#include "bvb/add_sat.h"
#include "target.h"

namespace bvb {
namespace {

Call add_call(const std::vector<uint8_t> &a, const std::vector<uint8_t> &b, int w, int h) {
  Call c;
  c.kernel = Registry::product().get("add_sat_u8").index;
  c.impl = BVB_IMPL_ASM;
  Buffer ba, bb, bd;
  ba.name = "a", ba.data = a;
  bb.name = "b", bb.data = b;
  bd.name = "dst", bd.data.assign(a.size(), 0);
  c.bufs = {ba, bb, bd};
  for (uint32_t i = 0; i < 3; ++i) c.args.push_back(Arg::buf(i));
  for (int v : {w, h, w, w, 0}) c.args.push_back(Arg::word(v));  // no scratch: the direct path
  return c;
}

std::vector<uint8_t> pattern(size_t n, int seed) {
  std::vector<uint8_t> v(n);
  for (size_t i = 0; i < n; ++i) v[i] = uint8_t(i * 13 + seed * 71);
  return v;
}

std::vector<uint8_t> host_sum(const std::vector<uint8_t> &a, const std::vector<uint8_t> &b, int w, int h) {
  std::vector<uint8_t> d(a.size());
  bvb_add_sat_u8_c(a.data(), b.data(), d.data(), w, h, w, w, nullptr);
  return d;
}

TEST(Session, ServesManyCallsInOneProcess) {
  Target target(product_firmware(), default_simulator());
  Session s(target);
  const int w = 21, h = 7;
  for (int frame = 0; frame < 5; ++frame) {
    auto a = pattern(w * h, frame), b = pattern(w * h, 100 + frame);
    CallResult r = s.call(add_call(a, b, w, h));
    ASSERT_EQ(r.status, uint32_t(BVB_OK)) << describe_failure(add_call(a, b, w, h), r);
    EXPECT_TRUE(r.guard_damage.empty());
    EXPECT_EQ(r.data[2], host_sum(a, b, w, h)) << "frame " << frame;
    EXPECT_GT(r.cycles, uint32_t(w * h));
  }
}

TEST(Session, PersistentBuffersKeepTheirWindowContents) {
  Target target(product_firmware(), default_simulator());
  Session s(target);
  const int w = 16, h = 4;
  auto a1 = pattern(w * h, 1), b1 = pattern(w * h, 2), a2 = pattern(w * h, 3), b2 = pattern(w * h, 4);
  Call first = add_call(a1, b1, w, h);
  first.bufs[0].persistent = true;
  EXPECT_EQ(s.call(first).data[2], host_sum(a1, b1, w, h));
  Call second = add_call(a2, b2, w, h);
  second.bufs[0].persistent = true;  // a2 is not written: the window still holds a1
  CallResult r = s.call(second);
  EXPECT_EQ(r.data[0], a1);
  EXPECT_EQ(r.data[2], host_sum(a1, b2, w, h));
}

}  // namespace
}  // namespace bvb
