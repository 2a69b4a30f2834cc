// Tests on the real frames (../shared/frames-real, outside the repository): without them a test
// is skipped with the reason shown, or fails when BVB_REQUIRE_FRAMES=1 (as CI runs), never run on
// something else under its name.
#pragma once

#include <gtest/gtest.h>

#include "patterns.h"

#define BVB_NEED_REAL_FRAMES(dir)                                              \
  do {                                                                         \
    if (!::bvb::frames_real_present(dir)) {                                    \
      if (::bvb::frames_required()) FAIL() << ::bvb::frames_missing_message(dir); \
      GTEST_SKIP() << ::bvb::frames_missing_message(dir);                      \
    }                                                                          \
  } while (0)
