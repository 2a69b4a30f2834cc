#include "io.h"

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include <unistd.h>

namespace bvb {

std::vector<uint8_t> read_file(const std::string &path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw InputError(path + ": cannot open: " + std::strerror(errno));
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  if (f.bad()) throw InputError(path + ": read error");
  return bytes;
}

void write_file_atomic(const std::string &path, const void *data, size_t size) {
  std::string tmp = path + ".tmp." + std::to_string(getpid());
  FILE *f = std::fopen(tmp.c_str(), "wb");
  if (!f) throw InputError(path + ": cannot write: " + std::strerror(errno));
  bool ok = std::fwrite(data, 1, size, f) == size;
  ok = (std::fflush(f) == 0) && ok;
  ok = (std::fclose(f) == 0) && ok;
  if (!ok || std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw InputError(path + ": write failed: " + std::strerror(errno));
  }
}

namespace {

// Reads the next header token of a Netpbm file, skipping whitespace and comments.
struct PnmHeader {
  const std::vector<uint8_t> &b;
  const std::string &name;
  size_t pos = 0;

  int number(const char *what) {
    for (;;) {
      while (pos < b.size() && std::isspace(b[pos])) ++pos;
      if (pos < b.size() && b[pos] == '#') {
        while (pos < b.size() && b[pos] != '\n') ++pos;
        continue;
      }
      break;
    }
    if (pos >= b.size() || !std::isdigit(b[pos]))
      throw InputError(name + ": malformed PNM header (expected " + what + ")");
    long v = 0;
    while (pos < b.size() && std::isdigit(b[pos])) {
      v = v * 10 + (b[pos++] - '0');
      if (v > 1000000) throw InputError(name + ": PNM " + what + " too large");
    }
    return int(v);
  }
};

}  // namespace

Image parse_pnm(const std::vector<uint8_t> &bytes, const std::string &name) {
  if (bytes.size() < 2 || bytes[0] != 'P' || !std::strchr("2356", bytes[1]) || bytes[1] == 0)
    throw InputError(name + ": not a PGM/PPM file (bad magic)");
  const char kind = char(bytes[1]);
  const bool ascii = kind == '2' || kind == '3';
  const int channels = (kind == '3' || kind == '6') ? 3 : 1;
  PnmHeader h{bytes, name};
  h.pos = 2;
  int w = h.number("width"), ht = h.number("height"), maxval = h.number("maxval");
  if (w <= 0 || ht <= 0) throw InputError(name + ": zero image size");
  if (w > kMaxFrameDim || ht > kMaxFrameDim)
    throw InputError(name + ": image " + std::to_string(w) + "x" + std::to_string(ht) +
                     " larger than " + std::to_string(kMaxFrameDim) + " pixels a side");
  if (maxval < 1 || maxval > 255) throw InputError(name + ": maxval must be 1..255 (8-bit only)");
  Image img(w, ht, channels);
  const size_t n = img.data.size();
  if (ascii) {
    for (size_t i = 0; i < n; ++i) {
      int v = h.number("pixel value");
      if (v > maxval) throw InputError(name + ": pixel value above maxval");
      img.data[i] = uint8_t(v);
    }
  } else {
    if (h.pos >= bytes.size() || !std::isspace(bytes[h.pos]))
      throw InputError(name + ": malformed PNM header");
    ++h.pos;
    if (bytes.size() - h.pos < n)
      throw InputError(name + ": truncated: " + std::to_string(bytes.size() - h.pos) + " of " +
                       std::to_string(n) + " pixel bytes");
    std::memcpy(img.data.data(), bytes.data() + h.pos, n);
  }
  if (maxval != 255)
    for (auto &p : img.data) p = uint8_t((p * 255 + maxval / 2) / maxval);
  return img;
}

Image read_pnm(const std::string &path) { return parse_pnm(read_file(path), path); }

std::vector<uint8_t> encode_pnm(const Image &img) {
  std::string hdr = std::string(img.channels == 3 ? "P6" : "P5") + "\n" +
                    std::to_string(img.width) + " " + std::to_string(img.height) + "\n255\n";
  std::vector<uint8_t> out(hdr.begin(), hdr.end());
  out.insert(out.end(), img.data.begin(), img.data.end());
  return out;
}

void write_pnm(const std::string &path, const Image &img) {
  if (img.channels != 1 && img.channels != 3)
    throw InputError(path + ": only grey or RGB images can be written as PNM");
  write_file_atomic(path, encode_pnm(img));
}

std::vector<uint8_t> read_uyvy(const std::string &path, int width, int height) {
  if (width <= 0 || height <= 0 || width > kMaxFrameDim || height > kMaxFrameDim)
    throw InputError(path + ": UYVY size out of range");
  if (width % 2) throw InputError(path + ": UYVY width must be even");
  auto bytes = read_file(path);
  const size_t need = size_t(width) * height * 2;
  if (bytes.size() != need)
    throw InputError(path + ": UYVY file has " + std::to_string(bytes.size()) +
                     " bytes, " + std::to_string(width) + "x" + std::to_string(height) +
                     " needs " + std::to_string(need));
  return bytes;
}

FlowField read_flo(const std::string &path) {
  auto b = read_file(path);
  if (b.size() < 12 || std::memcmp(b.data(), "PIEH", 4) != 0)
    throw InputError(path + ": not a .flo file (bad magic)");
  int32_t w, h;
  std::memcpy(&w, b.data() + 4, 4);
  std::memcpy(&h, b.data() + 8, 4);
  if (w <= 0 || h <= 0 || w > kMaxFrameDim || h > kMaxFrameDim)
    throw InputError(path + ": .flo size out of range");
  const size_t n = size_t(w) * h;
  if (b.size() != 12 + n * 8)
    throw InputError(path + ": .flo has " + std::to_string(b.size()) + " bytes, expected " +
                     std::to_string(12 + n * 8));
  FlowField f(w, h);
  const uint8_t *p = b.data() + 12;
  for (size_t i = 0; i < n; ++i, p += 8) {
    std::memcpy(&f.u[i], p, 4);
    std::memcpy(&f.v[i], p + 4, 4);
  }
  return f;
}

void write_flo(const std::string &path, const FlowField &flow) {
  const size_t n = size_t(flow.width) * flow.height;
  std::vector<uint8_t> b(12 + n * 8);
  std::memcpy(b.data(), "PIEH", 4);
  int32_t w = flow.width, h = flow.height;
  std::memcpy(b.data() + 4, &w, 4);
  std::memcpy(b.data() + 8, &h, 4);
  uint8_t *p = b.data() + 12;
  for (size_t i = 0; i < n; ++i, p += 8) {
    std::memcpy(p, &flow.u[i], 4);
    std::memcpy(p + 4, &flow.v[i], 4);
  }
  write_file_atomic(path, b);
}

}  // namespace bvb
