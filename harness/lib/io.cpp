#include "io.h"

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <cstdlib>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cleanup.h"
#include "names.h"

namespace bvb {

namespace {

std::string describe_type(mode_t m) {
  if (S_ISDIR(m)) return "a directory";
  if (S_ISCHR(m)) return "a character device";
  if (S_ISBLK(m)) return "a block device";
  if (S_ISFIFO(m)) return "a FIFO";
  if (S_ISSOCK(m)) return "a socket";
  return "not a regular file";
}

bool write_all(int fd, const void *data, size_t size) {
  const char *p = static_cast<const char *>(data);
  while (size > 0) {
    ssize_t n = ::write(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    size -= size_t(n);
  }
  return true;
}

}  // namespace

std::vector<uint8_t> read_file(const std::string &path, size_t max_bytes) {
  // open() rather than a stream: a stream reports a directory as an exception from deep in the
  // library with no file name, and reads a device like /dev/zero for ever.
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw InputError(path + ": cannot open: " + std::strerror(errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st;
  if (fstat(fd, &st) != 0) throw InputError(path + ": cannot stat: " + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw InputError(path + ": is a directory, not a file");
  const std::string limit = std::to_string(max_bytes) + " bytes";
  std::vector<uint8_t> bytes;
  if (S_ISREG(st.st_mode)) {
    if (uint64_t(st.st_size) > max_bytes)
      throw InputError(path + ": " + std::to_string(st.st_size) + " bytes, more than the " + limit +
                       " it may have");
    bytes.reserve(size_t(st.st_size));
  }
  // Devices and FIFOs have no size to check first: read until the limit, then refuse.
  uint8_t buf[65536];
  for (;;) {
    ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputError(path + ": read error: " + std::strerror(errno));
    if (n == 0) break;
    if (bytes.size() + size_t(n) > max_bytes)
      throw InputError(path + ": more than the " + limit + " it may have (" + describe_type(st.st_mode) +
                       " that does not end?)");
    bytes.insert(bytes.end(), buf, buf + n);
  }
  return bytes;
}

void write_file_atomic(const std::string &path, const void *data, size_t size) {
  struct stat st;
  bool exists = ::stat(path.c_str(), &st) == 0;  // follows symbolic links
  if (!exists && errno != ENOENT) throw InputError(path + ": cannot write: " + std::strerror(errno));
  std::string target = path;
  if (exists) {
    if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) {
      // Devices (/dev/null, a terminal) and FIFOs are streams the user chose: written straight,
      // never replaced by a regular file.
      int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
      if (fd < 0) throw InputError(path + ": cannot write: " + std::strerror(errno));
      bool ok = write_all(fd, data, size);
      int err = errno;
      ok = (::close(fd) == 0) && ok;
      if (!ok) throw InputError(path + ": write failed: " + std::strerror(err));
      return;
    }
    if (!S_ISREG(st.st_mode))
      throw InputError(path + ": is " + describe_type(st.st_mode) + ", not a file that can be written");
    // A symbolic link is followed: the file it names is replaced, the link stays a link.
    char *real = ::realpath(path.c_str(), nullptr);
    if (!real) throw InputError(path + ": cannot resolve: " + std::strerror(errno));
    target = real;
    std::free(real);
  } else {
    struct stat lst;
    if (::lstat(path.c_str(), &lst) == 0 && S_ISLNK(lst.st_mode))
      throw InputError(path + ": is a symbolic link to nothing; not written");
  }
  // The new contents go to a temporary file beside the target, renamed over it when complete: a
  // failed or interrupted run leaves the old file, never a half-written one.
  std::string tmp = target + ".tmp.XXXXXX";
  int fd = ::mkstemp(tmp.data());
  if (fd < 0) throw InputError(path + ": cannot write: " + std::strerror(errno));
  register_temp_file(tmp);
  bool ok = write_all(fd, data, size);
  int err = errno;
  if (ok && exists) ::fchmod(fd, st.st_mode & 07777);  // keep the replaced file's permissions
  else if (ok) {
    mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);  // as a newly created file would be (mkstemp makes 0600)
  }
  if (::close(fd) != 0 && ok) ok = false, err = errno;
  if (ok && std::rename(tmp.c_str(), target.c_str()) != 0) ok = false, err = errno;
  if (!ok) std::remove(tmp.c_str());
  unregister_temp_file(tmp);
  if (!ok) throw InputError(path + ": write failed: " + std::strerror(err));
}

FileLock::FileLock(const std::string &path, const std::function<void()> &on_wait) {
  const auto slash = path.rfind('/');
  const std::string dir = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
  fd_ = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ < 0) throw InputError(path + ": cannot lock its directory: " + std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) == 0) return;
  if (errno == EWOULDBLOCK && on_wait) on_wait();
  while (::flock(fd_, LOCK_EX) != 0) {
    if (errno == EINTR) continue;
    const int err = errno;
    ::close(fd_);
    fd_ = -1;
    throw InputError(path + ": cannot lock its directory: " + std::strerror(err));
  }
}

FileLock &FileLock::operator=(FileLock &&o) noexcept {
  if (this != &o) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = o.fd_;
    o.fd_ = -1;
  }
  return *this;
}

FileLock::~FileLock() {
  if (fd_ >= 0) ::close(fd_);  // closing releases the lock
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
  // The magic is two bytes and whitespace: "P55 ..." is not a P5 header.
  if (bytes.size() < 3 || !std::isspace(bytes[2])) throw InputError(name + ": not a PGM/PPM file (bad magic)");
  const char kind = char(bytes[1]);
  const bool ascii = kind == '2' || kind == '3';
  const int channels = (kind == '3' || kind == '6') ? 3 : 1;
  PnmHeader h{bytes, name};
  h.pos = 2;
  int w = h.number("width"), ht = h.number("height"), maxval = h.number("maxval");
  if (w <= 0 || ht <= 0) throw InputError(name + ": zero image size");
  if (w > kMaxFrameDim || ht > kMaxFrameDim)
    throw InputError(name + ": image " + size_name(w, ht) +
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
    for (size_t i = 0; i < n; ++i)
      if (img.data[i] > maxval)
        throw InputError(name + ": pixel value " + std::to_string(img.data[i]) + " above maxval " +
                         std::to_string(maxval) + " at byte " + std::to_string(h.pos + i));
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

namespace {

// The size checks come before the file is read: a bad --size costs no read.
void check_uyvy_size(const std::string &name, int width, int height) {
  if (width <= 0 || height <= 0 || width > kMaxFrameDim || height > kMaxFrameDim)
    throw InputError(name + ": UYVY size out of range");
  if (width % 2) throw InputError(name + ": UYVY width must be even");
}

}  // namespace

std::vector<uint8_t> parse_uyvy(std::vector<uint8_t> bytes, const std::string &name, int width, int height) {
  check_uyvy_size(name, width, height);
  const size_t need = size_t(width) * height * 2;
  if (bytes.size() != need)
    throw InputError(name + ": UYVY file has " + std::to_string(bytes.size()) +
                     " bytes, " + size_name(width, height) +
                     " needs " + std::to_string(need));
  return bytes;
}

std::vector<uint8_t> read_uyvy(const std::string &path, int width, int height) {
  check_uyvy_size(path, width, height);
  return parse_uyvy(read_file(path), path, width, height);
}

FlowField parse_flo(const std::vector<uint8_t> &b, const std::string &name) {
  if (b.size() < 12 || std::memcmp(b.data(), "PIEH", 4) != 0)
    throw InputError(name + ": not a .flo file (bad magic)");
  int32_t w, h;
  std::memcpy(&w, b.data() + 4, 4);
  std::memcpy(&h, b.data() + 8, 4);
  if (w <= 0 || h <= 0 || w > kMaxFrameDim || h > kMaxFrameDim)
    throw InputError(name + ": .flo size out of range");
  const size_t n = size_t(w) * h;
  if (b.size() != 12 + n * 8)
    throw InputError(name + ": .flo has " + std::to_string(b.size()) + " bytes, expected " +
                     std::to_string(12 + n * 8));
  FlowField f(w, h);
  const uint8_t *p = b.data() + 12;
  for (size_t i = 0; i < n; ++i, p += 8) {
    std::memcpy(&f.u[i], p, 4);
    std::memcpy(&f.v[i], p + 4, 4);
  }
  return f;
}

FlowField read_flo(const std::string &path) { return parse_flo(read_file(path), path); }

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
