#include "registry.h"

#include <stdexcept>

#include "io.h"

namespace bvb {

namespace {

std::vector<KernelInfo> expand_product() {
  std::vector<KernelInfo> k;
#define BVB_KERNEL(name, c_entry, asm_entry) k.push_back({#name, uint32_t(k.size()), true, #c_entry, #asm_entry});
#define BVB_KERNEL_C(name, c_entry) k.push_back({#name, uint32_t(k.size()), false, #c_entry, ""});
#include "kernels.def"
#undef BVB_KERNEL
#undef BVB_KERNEL_C
  return k;
}

std::vector<KernelInfo> expand_selftest() {
  std::vector<KernelInfo> k;
#define BVB_KERNEL(name, c_entry, asm_entry) k.push_back({#name, uint32_t(k.size()), true, #c_entry, #asm_entry});
#define BVB_KERNEL_C(name, c_entry) k.push_back({#name, uint32_t(k.size()), false, #c_entry, ""});
#include "selftest/selftest.def"
#undef BVB_KERNEL
#undef BVB_KERNEL_C
  return k;
}

// The product, and whether anything has read it yet (set_product is refused after).
struct ProductState {
  Product product{"bvb", expand_product(), BVB_FIRMWARE_ELF, BVB_SOURCE_DIR "/ci/budgets.json"};
  bool read = false;
};

ProductState &product_state() {
  static ProductState s;
  return s;
}

}  // namespace

const Product &product() {
  ProductState &s = product_state();
  s.read = true;
  return s.product;
}

void set_product(Product p) {
  ProductState &s = product_state();
  if (s.read) throw std::logic_error("set_product after the product was read");
  s.product = std::move(p);
}

std::string bfbench_name() {
  const std::string &n = product().name;
  return n == "bvb" ? "bfbench" : "bfbench-" + n;
}

const Registry &Registry::product() {
  static const Registry r(bvb::product().kernels);
  return r;
}

const Registry &Registry::selftest() {
  static const Registry r(expand_selftest());
  return r;
}

const KernelInfo *Registry::find(const std::string &name) const {
  for (const auto &k : kernels_)
    if (k.name == name) return &k;
  return nullptr;
}

const KernelInfo &Registry::get(const std::string &name) const {
  if (const KernelInfo *k = find(name)) return *k;
  throw InputError("unknown kernel '" + name + "' (bfbench list shows them)");
}

uint32_t Registry::hash() const {
  uint32_t h = 2166136261u;
  for (const auto &k : kernels_) {
    for (char c : k.name) {
      h ^= uint8_t(c);
      h *= 16777619u;
    }
    h *= 16777619u;  // the terminating NUL: h ^= 0 leaves h as it is
  }
  return h;
}

const char *impl_name(uint32_t impl) {
  switch (impl) {
    case BVB_IMPL_C: return "c";
    case BVB_IMPL_ASM: return "asm";
    default: return "?";
  }
}

uint32_t parse_impl(const std::string &s) {
  if (s == "c") return BVB_IMPL_C;
  if (s == "asm") return BVB_IMPL_ASM;
  throw InputError("unknown implementation '" + s + "' (c, asm or host)");
}

bool glob_match(const std::string &p, const std::string &t) {
  size_t pi = 0, ti = 0, star = std::string::npos, mark = 0;
  while (ti < t.size()) {
    if (pi < p.size() && (p[pi] == '?' || p[pi] == t[ti])) {
      ++pi, ++ti;
    } else if (pi < p.size() && p[pi] == '*') {
      star = pi++;
      mark = ti;
    } else if (star != std::string::npos) {
      pi = star + 1;
      ti = ++mark;
    } else {
      return false;
    }
  }
  while (pi < p.size() && p[pi] == '*') ++pi;
  return pi == p.size();
}

}  // namespace bvb
