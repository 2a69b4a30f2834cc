#include "family.h"

#include <cstdlib>

#include "io.h"

namespace bvb {

void Params::set(const std::string &kv) {
  auto eq = kv.find('=');
  if (eq == std::string::npos || eq == 0) throw InputError("--param wants K=V, got '" + kv + "'");
  values_[kv.substr(0, eq)] = kv.substr(eq + 1);
}

int Params::get_int(const std::string &key, int fallback, int lo, int hi) {
  used_.insert(key);
  auto it = values_.find(key);
  if (it == values_.end()) return fallback;
  char *end = nullptr;
  long v = std::strtol(it->second.c_str(), &end, 10);
  if (it->second.empty() || *end || v < lo || v > hi)
    throw InputError("parameter " + key + "=" + it->second + ": want an integer in " +
                     std::to_string(lo) + ".." + std::to_string(hi));
  return int(v);
}

std::string Params::get_str(const std::string &key, const std::string &fallback) {
  used_.insert(key);
  auto it = values_.find(key);
  return it == values_.end() ? fallback : it->second;
}

void Params::check_all_used() const {
  for (const auto &kv : values_)
    if (!used_.count(kv.first)) throw InputError("unknown parameter '" + kv.first + "' for this kernel");
}

std::vector<const Family *> &families() {
  static std::vector<const Family *> f;
  return f;
}

bool register_family(const Family *f) {
  families().push_back(f);
  return true;
}

const Family *family_of(const std::string &kernel) {
  for (const Family *f : families())
    for (const auto &k : f->kernels)
      if (k == kernel) return f;
  return nullptr;
}

Image read_frame(const std::string &path, int raw_w, int raw_h, bool want_grey) {
  const bool raw = path.size() > 5 && path.compare(path.size() - 5, 5, ".uyvy") == 0;
  if (raw) {
    if (raw_w <= 0 || raw_h <= 0) throw InputError(path + ": raw UYVY input needs --size WxH");
    auto bytes = read_uyvy(path, raw_w, raw_h);
    Image img(raw_w, raw_h);
    for (size_t i = 0; i < img.data.size(); ++i) img.data[i] = bytes[2 * i + 1];  // the Y bytes
    return img;
  }
  Image img = read_pnm(path);
  if (want_grey && img.channels == 3) {
    Image g(img.width, img.height);
    for (size_t i = 0; i < g.data.size(); ++i) {
      const uint8_t *p = &img.data[3 * i];
      g.data[i] = uint8_t((77 * p[0] + 150 * p[1] + 29 * p[2] + 128) >> 8);
    }
    return g;
  }
  return img;
}

}  // namespace bvb
