/* The registry table, expanded from the kernel list this image is built with (BVB_KERNEL_LIST):
 * kernels.def for the product, selftest/selftest.def for the self-test image. The entries are
 * only called through bvb_call with word arguments, so they are declared here without their
 * prototypes. */
#include "registry.h"

#define BVB_KERNEL(name, c_entry, asm_entry) extern void c_entry(void); extern void asm_entry(void);
#define BVB_KERNEL_C(name, c_entry) extern void c_entry(void);
#include BVB_KERNEL_LIST
#undef BVB_KERNEL
#undef BVB_KERNEL_C

const struct bvb_kernel bvb_kernels[] = {
#define BVB_KERNEL(name, c_entry, asm_entry) {#name, {c_entry, asm_entry}},
#define BVB_KERNEL_C(name, c_entry) {#name, {c_entry, 0}},
#include BVB_KERNEL_LIST
#undef BVB_KERNEL
#undef BVB_KERNEL_C
};

const uint32_t bvb_kernel_count = sizeof bvb_kernels / sizeof bvb_kernels[0];
