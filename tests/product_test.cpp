// The product bfbench works on (registry.h): this tree's by default, and fixed once read.
#include <stdexcept>

#include <gtest/gtest.h>

#include "registry.h"
#include "target.h"

namespace bvb {
namespace {

TEST(Product, DefaultIsThisTreesKernelsImageAndBudgets) {
  const Product &p = product();
  EXPECT_EQ(p.name, "bvb");
  ASSERT_EQ(p.kernels.size(), Registry::product().kernels().size());
  for (size_t i = 0; i < p.kernels.size(); ++i) EXPECT_EQ(p.kernels[i].name, Registry::product().kernels()[i].name);
  EXPECT_NE(Registry::product().find("add_sat_u8"), nullptr);
  EXPECT_EQ(p.budgets, std::string(BVB_SOURCE_DIR) + "/ci/budgets.json");
  EXPECT_EQ(p.elf.substr(p.elf.size() - 8), "/bvb.elf");
}

TEST(Product, CannotChangeOnceRead) {
  const size_t n = product().kernels.size();
  Product other{"other", {{"k", 0, true, "k_c", "k_asm"}}, "/nonexistent.elf", "/nonexistent.json"};
  EXPECT_THROW(set_product(other), std::logic_error);
  EXPECT_EQ(product().name, "bvb");
  EXPECT_EQ(product().kernels.size(), n);
}

}  // namespace
}  // namespace bvb
