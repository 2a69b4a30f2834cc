// The one place that writes and reads the names the harness prints and takes back: frame sizes
// ("320x240"), check calls ("sobel3x3_u8:17", as a failure prints it and --case takes it) and
// budget keys ("sobel3x3_u8/asm/320x240"). What one command prints, another parses.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace bvb {

struct Size {
  int w, h;
};

// "WxH".
std::string size_name(int w, int h);
inline std::string size_name(Size s) { return size_name(s.w, s.h); }
// "WxH" with 1 <= W, H <= max_dim, the whole string (no signs, spaces or trailing text); false
// otherwise, *out untouched.
bool parse_size(const std::string &text, int max_dim, Size *out);
// A size at the start of text ("320x240 stride 336" gives 320x240), for names that go on.
bool parse_size_prefix(const std::string &text, Size *out);

// A check call's identity: "KERNEL:N", N the family's call number.
std::string case_id(const std::string &kernel, uint64_t n);
// KERNEL:N with a non-empty kernel and N all digits; false otherwise.
bool parse_case_id(const std::string &text, std::string *kernel, uint64_t *n = nullptr);
// The kernel of a KERNEL:N (the text before the last colon; all of it when there is none).
std::string case_kernel(const std::string &id);

// A kernel's implementation as reports name it: "KERNEL (IMPL)", e.g. "sobel3x3_u8 (asm)".
std::string kernel_impl_name(const std::string &kernel, const std::string &impl);

// A budget's key: "KERNEL/IMPL/CASE".
std::string budget_key(const std::string &kernel, const std::string &impl, const std::string &case_name);
// The kernel of a budget key (the text before the first slash).
std::string budget_key_kernel(const std::string &key);
// The case of a budget key (the text after the last slash).
std::string budget_key_case(const std::string &key);

// The items of a comma-separated list ("a,b" gives a and b; "" gives one empty item): option
// names ("-k,--kernel"), scene specs.
std::vector<std::string> split_list(const std::string &text);

}  // namespace bvb
