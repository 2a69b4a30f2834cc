// The host's view of a firmware image's kernel registry, expanded from the same list file the
// firmware is built from (firmware/kernels.def, or firmware/selftest/selftest.def, or a kernel
// family's own list when bfbench was built for one outside this tree: see Product).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "bvb/mailbox.h"

namespace bvb {

struct KernelInfo {
  std::string name;
  uint32_t index;
  bool has_asm;
  std::string c_entry, asm_entry;  // the entries' C names (asm_entry empty for C only)
};

class Registry {
 public:
  explicit Registry(std::vector<KernelInfo> kernels) : kernels_(std::move(kernels)) {}
  static const Registry &product();
  static const Registry &selftest();

  const std::vector<KernelInfo> &kernels() const { return kernels_; }
  const KernelInfo *find(const std::string &name) const;
  const KernelInfo &get(const std::string &name) const;  // throws InputError if unknown
  uint32_t hash() const;  // as the firmware computes it (FNV-1a of names with their NULs)

 private:
  std::vector<KernelInfo> kernels_;
};

// What bfbench works on unless an option says otherwise: this tree's kernels (kernels.def),
// firmware image (bvb.elf) and budgets file (ci/budgets.json); or, in the bfbench that
// bvb_add_kernel_family (cmake/bvb-kernel-family.cmake) builds for a family outside this tree,
// that family's kernels, its image of them and its budgets file. Registry::product(),
// product_firmware() and bfbench budgets read it.
struct Product {
  std::string name;  // "bvb", or the family's
  std::vector<KernelInfo> kernels;
  std::string elf;
  std::string budgets;
};
const Product &product();
// Replaces the product; only before anything has read it (a std::logic_error after), so no
// part of a run can see the other one.
void set_product(Product p);
// The command that works on the product, for the commands a report prints: "bfbench", or the
// family's "bfbench-NAME".
std::string bfbench_name();

const char *impl_name(uint32_t impl);  // "c", "asm"
uint32_t parse_impl(const std::string &s);  // throws InputError

// Shell-style glob with * and ?, for -k filters.
bool glob_match(const std::string &pattern, const std::string &text);

}  // namespace bvb
