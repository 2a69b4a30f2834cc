// A directory of the test's own: ctest runs each test in a process of its own and many at once
// (-j), so files named alike in one shared directory (testing::TempDir()) would race. Made on
// first use under TempDir(), removed with its contents when the process ends.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace bvb {

inline const std::string &test_dir() {
  struct Dir {
    std::string path;
    Dir() {
      std::string tmpl = testing::TempDir() + "bvb-test-XXXXXX";
      if (!mkdtemp(&tmpl[0])) throw std::runtime_error("mkdtemp " + tmpl + " failed");
      path = tmpl + "/";
    }
    ~Dir() {
      std::error_code ec;
      std::filesystem::remove_all(path, ec);
    }
  };
  static const Dir d;
  return d.path;
}

}  // namespace bvb
