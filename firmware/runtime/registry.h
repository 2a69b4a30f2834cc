#ifndef BVB_REGISTRY_H
#define BVB_REGISTRY_H

#include <stdint.h>

#include "bvb/mailbox.h"

struct bvb_kernel {
  const char *name;
  void (*entry[BVB_IMPL_COUNT])(void); /* by enum bvb_impl; 0 where there is none */
};

extern const struct bvb_kernel bvb_kernels[];
extern const uint32_t bvb_kernel_count;

#endif
