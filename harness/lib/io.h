// File I/O for the harness: every reader rejects malformed input with an InputError carrying one
// line that names the file and the problem; every writer writes a temporary file next to the
// target and renames it, so a failed run never leaves a half-written output (devices and FIFOs,
// which cannot be renamed over, are written straight).
#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "image.h"

namespace bvb {

// Bad input from the user (malformed file, bad size, unknown name): bfbench exits 2 on it.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// A kernel's call failed its check (a wrong result, a fault, a clobbered register) where the
// command cannot go on without it (a pipeline's frame, the profiled call): exit 1, as a failed
// check is.
struct CallFailed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Sizes the harness accepts for any frame: large enough for every kernel's memory map.
constexpr int kMaxFrameDim = 4096;
// The most any input file may hold: a 4096x4096 .flo (8 bytes a pixel) with its header, the
// largest legitimate input. Checked before reading, so /dev/zero cannot exhaust memory.
constexpr size_t kMaxInputBytes = 12 + size_t(kMaxFrameDim) * kMaxFrameDim * 8;

// Reads a whole file; a directory, a file over max_bytes, or a device or FIFO that gives more
// is an InputError naming the file.
std::vector<uint8_t> read_file(const std::string &path, size_t max_bytes = kMaxInputBytes);
// Writes a file whole. A new path or a regular file is written to a temporary file and renamed
// over it; a symbolic link is followed (the file it names is replaced, the link kept); a
// character device (/dev/null) or a FIFO is written straight; anything else is refused.
void write_file_atomic(const std::string &path, const void *data, size_t size);
inline void write_file_atomic(const std::string &path, const std::string &text) {
  write_file_atomic(path, text.data(), text.size());
}
inline void write_file_atomic(const std::string &path, const std::vector<uint8_t> &bytes) {
  write_file_atomic(path, bytes.data(), bytes.size());
}

// An exclusive advisory lock (flock) on the directory holding a file, held while the object
// lives. Files written by rename cannot carry the lock themselves: a process waiting on the old
// file would wake up holding a lock on a file nobody else opens any more.
class FileLock {
 public:
  FileLock() = default;
  // Blocks until the lock is free; calls on_wait first if another process holds it.
  FileLock(const std::string &path, const std::function<void()> &on_wait);
  FileLock(FileLock &&o) noexcept : fd_(o.fd_) { o.fd_ = -1; }
  FileLock &operator=(FileLock &&o) noexcept;
  ~FileLock();

 private:
  int fd_ = -1;
};

// Each format's reader is read_file and a parse_* of the bytes: the parse_* functions are the one
// parsing code path, also what the fuzz targets (fuzz/) call. `name` is the file named in errors.

// Netpbm: P2/P5 (grey) and P3/P6 (RGB), maxval 1..255. Writers emit binary P5/P6.
Image read_pnm(const std::string &path);
Image parse_pnm(const std::vector<uint8_t> &bytes, const std::string &name);
void write_pnm(const std::string &path, const Image &img);
std::vector<uint8_t> encode_pnm(const Image &img);

// Raw UYVY 4:2:2 (byte order U Y0 V Y1, the SRV-1 camera's): width must be even.
std::vector<uint8_t> read_uyvy(const std::string &path, int width, int height);
std::vector<uint8_t> parse_uyvy(std::vector<uint8_t> bytes, const std::string &name, int width, int height);

// Middlebury .flo: "PIEH", int32 width, int32 height, then interleaved float32 (u, v).
FlowField read_flo(const std::string &path);
FlowField parse_flo(const std::vector<uint8_t> &bytes, const std::string &name);
void write_flo(const std::string &path, const FlowField &flow);

}  // namespace bvb
