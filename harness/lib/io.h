// File I/O for the harness: every reader rejects malformed input with an InputError carrying one
// line that names the file and the problem; every writer writes a temporary file next to the
// target and renames it, so a failed run never leaves a half-written output.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "image.h"

namespace bvb {

// Bad input from the user (malformed file, bad size, unknown name): bfbench exits 2 on it.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::vector<uint8_t> read_file(const std::string &path);
void write_file_atomic(const std::string &path, const void *data, size_t size);
inline void write_file_atomic(const std::string &path, const std::vector<uint8_t> &bytes) {
  write_file_atomic(path, bytes.data(), bytes.size());
}

// Netpbm: P2/P5 (grey) and P3/P6 (RGB), maxval 1..255. Writers emit binary P5/P6.
Image read_pnm(const std::string &path);
Image parse_pnm(const std::vector<uint8_t> &bytes, const std::string &name);
void write_pnm(const std::string &path, const Image &img);
std::vector<uint8_t> encode_pnm(const Image &img);

// Raw UYVY 4:2:2 (byte order U Y0 V Y1, the SRV-1 camera's): width must be even.
std::vector<uint8_t> read_uyvy(const std::string &path, int width, int height);

// Middlebury .flo: "PIEH", int32 width, int32 height, then interleaved float32 (u, v).
FlowField read_flo(const std::string &path);
void write_flo(const std::string &path, const FlowField &flow);

// Sizes the harness accepts for any frame: large enough for every kernel's memory map.
constexpr int kMaxFrameDim = 4096;

}  // namespace bvb
