#include "names.h"

#include <cctype>

namespace bvb {

std::string size_name(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

namespace {

// Leading decimal digits of text from *pos as an int (at most 9 digits, so no overflow).
bool digits(const std::string &text, size_t *pos, int *out) {
  const size_t start = *pos;
  long v = 0;
  while (*pos < text.size() && std::isdigit(uint8_t(text[*pos])) && *pos - start < 9)
    v = v * 10 + (text[(*pos)++] - '0');
  if (*pos == start || (*pos < text.size() && std::isdigit(uint8_t(text[*pos])))) return false;
  *out = int(v);
  return true;
}

bool size_at_start(const std::string &text, size_t *pos, Size *out) {
  int w = 0, h = 0;
  if (!digits(text, pos, &w) || *pos >= text.size() || text[*pos] != 'x') return false;
  ++*pos;
  if (!digits(text, pos, &h)) return false;
  *out = {w, h};
  return true;
}

}  // namespace

bool parse_size(const std::string &text, int max_dim, Size *out) {
  size_t pos = 0;
  Size s{0, 0};
  if (!size_at_start(text, &pos, &s) || pos != text.size()) return false;
  if (s.w < 1 || s.h < 1 || s.w > max_dim || s.h > max_dim) return false;
  *out = s;
  return true;
}

bool parse_size_prefix(const std::string &text, Size *out) {
  size_t pos = 0;
  Size s{0, 0};
  if (!size_at_start(text, &pos, &s) || (pos < text.size() && text[pos] != ' ')) return false;
  *out = s;
  return true;
}

std::string case_id(const std::string &kernel, uint64_t n) { return kernel + ":" + std::to_string(n); }

bool parse_case_id(const std::string &text, std::string *kernel, uint64_t *n) {
  const size_t colon = text.rfind(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == text.size() || colon + 1 + 19 < text.size())
    return false;
  uint64_t v = 0;
  for (size_t i = colon + 1; i < text.size(); ++i) {
    if (!std::isdigit(uint8_t(text[i]))) return false;
    v = v * 10 + uint64_t(text[i] - '0');
  }
  *kernel = text.substr(0, colon);
  if (n) *n = v;
  return true;
}

std::string case_kernel(const std::string &id) { return id.substr(0, id.rfind(':')); }

std::string kernel_impl_name(const std::string &kernel, const std::string &impl) {
  return kernel + " (" + impl + ")";
}

std::string budget_key(const std::string &kernel, const std::string &impl, const std::string &case_name) {
  return kernel + "/" + impl + "/" + case_name;
}

std::string budget_key_kernel(const std::string &key) { return key.substr(0, key.find('/')); }

std::string budget_key_case(const std::string &key) {
  const size_t slash = key.rfind('/');
  return slash == std::string::npos ? key : key.substr(slash + 1);
}

std::vector<std::string> split_list(const std::string &text) {
  std::vector<std::string> out;
  for (size_t a = 0, b; a <= text.size(); a = b + 1) {
    b = text.find(',', a);
    if (b == std::string::npos) b = text.size();
    out.push_back(text.substr(a, b - a));
  }
  return out;
}

}  // namespace bvb
