#include "elf_symbols.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>
#include <mutex>
#include <vector>

#include "io.h"

namespace bvb {

namespace {

struct Symbol {
  uint32_t value, size;
  std::string name;
};

template <class T> bool get(const std::vector<uint8_t> &b, size_t off, T *out) {
  if (off + sizeof(T) > b.size()) return false;
  std::memcpy(out, b.data() + off, sizeof(T));
  return true;
}

// The function symbols of a little-endian ELF32 image, sorted by address.
std::vector<Symbol> load_symbols(const std::string &path) {
  std::vector<Symbol> syms;
  std::vector<uint8_t> b;
  try {
    b = read_file(path);
  } catch (const InputError &) {
    return syms;
  }
  if (b.size() < 52 || std::memcmp(b.data(), "\x7f" "ELF", 4) != 0 || b[4] != 1 || b[5] != 1) return syms;
  uint32_t shoff;
  uint16_t shentsize, shnum;
  if (!get(b, 32, &shoff) || !get(b, 46, &shentsize) || !get(b, 48, &shnum) || shentsize < 40) return syms;
  for (uint16_t i = 0; i < shnum; ++i) {
    const size_t sh = shoff + size_t(i) * shentsize;
    uint32_t type = 0, offset = 0, size = 0, link = 0, entsize = 0;
    if (!get(b, sh + 4, &type) || type != 2 /* SHT_SYMTAB */) continue;
    get(b, sh + 16, &offset);
    get(b, sh + 20, &size);
    get(b, sh + 24, &link);
    get(b, sh + 36, &entsize);
    uint32_t stroff = 0, strsize = 0;
    const size_t strsh = shoff + size_t(link) * shentsize;
    if (!get(b, strsh + 16, &stroff) || !get(b, strsh + 20, &strsize)) return syms;
    if (entsize < 16) return syms;
    for (uint32_t s = 0; s + entsize <= size; s += entsize) {
      uint32_t name, value, ssize;
      uint8_t info;
      if (!get(b, offset + s, &name) || !get(b, offset + s + 4, &value) ||
          !get(b, offset + s + 8, &ssize) || !get(b, offset + s + 12, &info))
        break;
      const int kind = info & 0xf;
      if ((kind != 2 /* FUNC */ && kind != 0 /* NOTYPE */) || name >= strsize) continue;
      const char *n = reinterpret_cast<const char *>(b.data() + stroff + name);
      size_t len = strnlen(n, strsize - name);
      std::string sname(n, len);
      // Local labels (.L...) are not functions; C symbols carry the ABI's leading underscore.
      if (sname.empty() || sname[0] == '.' || sname[0] == '$') continue;
      if (sname[0] == '_') sname.erase(0, 1);
      syms.push_back({value, ssize, sname});
    }
  }
  std::sort(syms.begin(), syms.end(), [](const Symbol &a, const Symbol &c) { return a.value < c.value; });
  return syms;
}

}  // namespace

const std::vector<Symbol> &symbols(const std::string &elf_path) {
  static std::mutex mu;
  static std::map<std::string, std::vector<Symbol>> cache;
  std::lock_guard<std::mutex> lock(mu);
  auto it = cache.find(elf_path);
  if (it == cache.end()) it = cache.emplace(elf_path, load_symbols(elf_path)).first;
  return it->second;
}

bool symbol_value(const std::string &elf_path, const std::string &name, uint32_t *value) {
  for (const auto &s : symbols(elf_path))
    if (s.name == name) {
      *value = s.value;
      return true;
    }
  return false;
}

std::string symbolize(const std::string &elf_path, uint32_t address) {
  const auto &syms = symbols(elf_path);
  auto up = std::upper_bound(syms.begin(), syms.end(), address,
                             [](uint32_t a, const Symbol &s) { return a < s.value; });
  if (up == syms.begin()) return "";
  // The nearest function symbol at or below the address, if the address is inside it.
  for (auto s = up; s != syms.begin();) {
    --s;
    if (s->size && address >= s->value + s->size) continue;
    if (address - s->value > 0x10000) return "";
    char buf[32];
    std::snprintf(buf, sizeof buf, "+0x%x", address - s->value);
    return s->name + buf;
  }
  return "";
}

}  // namespace bvb
