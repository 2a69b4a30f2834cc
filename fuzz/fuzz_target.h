// What every fuzz target checks. A parser given any bytes must either return a value that keeps
// its documented limits or reject the input with an InputError (bfbench prints it as one line and
// exits 2). Anything else is a finding, reported by aborting so libFuzzer saves the input: another
// exception (bfbench would say "internal error"), a sanitizer report (ASan, UBSan), a crash, an
// input that runs past -timeout, or memory past -rss_limit_mb / -malloc_limit_mb.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <optional>
#include <string>
#include <typeinfo>
#include <vector>

#include "io.h"

namespace bvb::fuzz {

[[noreturn]] inline void finding(const std::string &what) {
  std::fprintf(stderr, "fuzz finding: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

// Runs parse(); its value, or nothing when it rejected the input with an InputError.
template <class Parse>
auto parse_or_reject(Parse &&parse) -> std::optional<decltype(parse())> {
  try {
    return parse();
  } catch (const InputError &) {
    return std::nullopt;
  } catch (const std::exception &e) {
    finding(std::string("uncaught ") + typeid(e).name() + ": " + e.what());
  } catch (...) {
    finding("uncaught exception of unknown type");
  }
}

inline std::vector<uint8_t> bytes_of(const uint8_t *data, size_t size) { return {data, data + size}; }
inline std::string text_of(const uint8_t *data, size_t size) {
  return std::string(reinterpret_cast<const char *>(data), size);
}

}  // namespace bvb::fuzz

// The libFuzzer entry point; each target file defines it once.
#define BVB_FUZZ_TARGET extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
