#include "formats.h"

#include <png.h>

#include <algorithm>
#include <cctype>
#include <cstring>

#include "io.h"
#include "names.h"

namespace bvb {

namespace {

std::string lower(std::string s) {
  for (auto &c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

const char *kKnownExtensions = ".pgm, .ppm, .pnm, .png, .flo, .npy, .csv, .txt or .uyvy";

// The extension of the last path component, with its dot, lower case; "" when there is none.
std::string extension(const std::string &path) {
  const size_t slash = path.rfind('/');
  const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  const size_t dot = base.rfind('.');
  if (dot == std::string::npos || dot == 0) return "";
  return lower(base.substr(dot));
}

}  // namespace

FileFormat format_of(const std::string &path) {
  const std::string ext = extension(path);
  if (ext.empty()) return FileFormat::None;
  if (ext == ".pgm" || ext == ".ppm" || ext == ".pnm") return FileFormat::Pnm;
  if (ext == ".png") return FileFormat::Png;
  if (ext == ".flo") return FileFormat::Flo;
  if (ext == ".npy") return FileFormat::Npy;
  if (ext == ".csv" || ext == ".txt") return FileFormat::Text;
  if (ext == ".uyvy") return FileFormat::Uyvy;
  throw InputError(path + ": unknown extension '" + ext + "' (known: " + kKnownExtensions + ")");
}

void check_output_name(const std::string &path, OutputKind kind) {
  const FileFormat f = format_of(path);
  if (f == FileFormat::None || f == FileFormat::Npy) return;
  const bool image = f == FileFormat::Pnm || f == FileFormat::Png;
  switch (kind) {
    case OutputKind::Image:
      if (!image) throw InputError(path + ": an image is written as .pgm, .ppm, .pnm, .png or .npy");
      return;
    case OutputKind::Flow:
      if (f != FileFormat::Flo) throw InputError(path + ": a flow field is written as .flo or .npy");
      return;
    case OutputKind::Text:
      if (f != FileFormat::Text) throw InputError(path + ": this output is text, written as .csv, .txt or .npy");
      return;
    case OutputKind::ImageOrText:
      if (!image && f != FileFormat::Text)
        throw InputError(path + ": this output is an image (.pgm, .ppm, .pnm, .png) or text (.csv, .txt), or .npy");
      return;
  }
}

// ---------------------------------------------------------------------------------------------
// PNG, through libpng's simplified API (it reports errors in png_image::message, no longjmp).

Image parse_png(const std::vector<uint8_t> &bytes, const std::string &name) {
  png_image im;
  std::memset(&im, 0, sizeof im);
  im.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&im, bytes.data(), bytes.size()))
    throw InputError(name + ": not a readable PNG file (" + im.message + ")");
  struct Release {
    png_image *p;
    ~Release() { png_image_free(p); }
  } release{&im};
  if (im.format & PNG_FORMAT_FLAG_ALPHA)
    throw InputError(name + ": PNG with transparency; only 8-bit grey or RGB PNGs are read");
  if (im.format & PNG_FORMAT_FLAG_LINEAR)
    throw InputError(name + ": 16-bit PNG; only 8-bit grey or RGB PNGs are read");
  if (im.width < 1 || im.height < 1 || im.width > uint32_t(kMaxFrameDim) || im.height > uint32_t(kMaxFrameDim))
    throw InputError(name + ": image " + size_name(im.width, im.height) +
                     " outside 1.." + std::to_string(kMaxFrameDim) + " pixels a side");
  const bool colour = (im.format & PNG_FORMAT_FLAG_COLOR) != 0;
  im.format = colour ? PNG_FORMAT_RGB : PNG_FORMAT_GRAY;
  Image img(int(im.width), int(im.height), colour ? 3 : 1);
  if (!png_image_finish_read(&im, nullptr, img.data.data(), 0, nullptr))
    throw InputError(name + ": malformed PNG (" + im.message + ")");
  return img;
}

std::vector<uint8_t> encode_png(const Image &img, const std::string &name) {
  if (img.channels != 1 && img.channels != 3)
    throw InputError(name + ": only grey or RGB images can be written as PNG");
  png_image im;
  std::memset(&im, 0, sizeof im);
  im.version = PNG_IMAGE_VERSION;
  im.width = png_uint_32(img.width);
  im.height = png_uint_32(img.height);
  im.format = img.channels == 3 ? PNG_FORMAT_RGB : PNG_FORMAT_GRAY;
  png_alloc_size_t size = 0;
  // First the size, then the bytes.
  if (!png_image_write_to_memory(&im, nullptr, &size, 0, img.data.data(), 0, nullptr))
    throw InputError(name + ": PNG encoding failed (" + im.message + ")");
  std::vector<uint8_t> out(size);
  if (!png_image_write_to_memory(&im, out.data(), &size, 0, img.data.data(), 0, nullptr))
    throw InputError(name + ": PNG encoding failed (" + im.message + ")");
  out.resize(size);
  return out;
}

// ---------------------------------------------------------------------------------------------
// NumPy .npy

namespace {

size_t npy_elem_bytes(const std::string &dtype) {
  static const char *known[] = {"|u1", "|i1", "<u2", "<i2", "<u4", "<i4", "<f4"};
  for (const char *k : known)
    if (dtype == k) return size_t(k[2] - '0');
  return 0;
}

}  // namespace

std::string npy_int_dtype(int bytes, bool is_signed) {
  const char kind = is_signed ? 'i' : 'u';
  return std::string(bytes == 1 ? "|" : "<") + kind + std::to_string(bytes);
}

std::vector<uint8_t> encode_npy(const NpyArray &a) {
  std::string shape = "(";
  for (size_t i = 0; i < a.shape.size(); ++i) shape += (i ? ", " : "") + std::to_string(a.shape[i]);
  shape += a.shape.size() == 1 ? ",)" : ")";
  std::string header = "{'descr': '" + a.dtype + "', 'fortran_order': False, 'shape': " + shape + ", }";
  // Magic (6), version (2), header length (2), then the header padded with spaces and ended by
  // a newline so that the data starts on a 64-byte boundary, as NumPy writes it.
  const size_t prefix = 10;
  const size_t total = (prefix + header.size() + 1 + 63) / 64 * 64;
  header.append(total - prefix - header.size() - 1, ' ');
  header += '\n';
  std::vector<uint8_t> out(prefix + header.size() + a.data.size());
  const uint8_t magic[prefix] = {0x93, 'N', 'U', 'M', 'P', 'Y', 1, 0, uint8_t(header.size() & 0xff),
                                 uint8_t(header.size() >> 8)};
  std::memcpy(out.data(), magic, prefix);
  std::memcpy(out.data() + prefix, header.data(), header.size());
  if (!a.data.empty()) std::memcpy(out.data() + prefix + header.size(), a.data.data(), a.data.size());
  return out;
}

NpyArray parse_npy(const std::vector<uint8_t> &b, const std::string &name) {
  auto bad = [&](const std::string &why) { return InputError(name + ": not a readable .npy file (" + why + ")"); };
  if (b.size() < 10 || std::memcmp(b.data(), "\x93NUMPY", 6) != 0) throw bad("bad magic");
  const int major = b[6];
  size_t hlen = 0, start = 0;
  if (major == 1) {
    hlen = size_t(b[8]) | size_t(b[9]) << 8;
    start = 10;
  } else if (major == 2 || major == 3) {
    if (b.size() < 12) throw bad("truncated header");
    hlen = size_t(b[8]) | size_t(b[9]) << 8 | size_t(b[10]) << 16 | size_t(b[11]) << 24;
    start = 12;
  } else {
    throw bad("format version " + std::to_string(major));
  }
  if (hlen > b.size() - start) throw bad("truncated header");
  const std::string h(b.begin() + long(start), b.begin() + long(start + hlen));
  // The header is a Python dict literal of three keys; read just those, strictly.
  auto value_after = [&](const std::string &key) {
    const size_t k = h.find("'" + key + "'");
    if (k == std::string::npos) throw bad("no '" + key + "'");
    size_t p = k + key.size() + 2;
    while (p < h.size() && (h[p] == ' ' || h[p] == ':')) ++p;
    return p;
  };
  NpyArray a;
  size_t p = value_after("descr");
  if (p >= h.size() || h[p] != '\'') throw bad("descr is not a string");
  const size_t q = h.find('\'', p + 1);
  if (q == std::string::npos) throw bad("descr is not a string");
  a.dtype = h.substr(p + 1, q - p - 1);
  if (a.dtype == "u1" || a.dtype == "<u1") a.dtype = "|u1";
  if (a.dtype == "i1" || a.dtype == "<i1") a.dtype = "|i1";
  const size_t elem = npy_elem_bytes(a.dtype);
  if (!elem) throw bad("element type '" + a.dtype + "' is not one of |u1 |i1 <u2 <i2 <u4 <i4 <f4");
  p = value_after("fortran_order");
  if (h.compare(p, 5, "False") != 0) throw bad("Fortran order");
  p = value_after("shape");
  if (p >= h.size() || h[p] != '(') throw bad("shape is not a tuple");
  ++p;
  size_t count = 1;
  for (;;) {
    while (p < h.size() && h[p] == ' ') ++p;
    if (p < h.size() && h[p] == ')') break;
    if (p >= h.size() || !std::isdigit(static_cast<unsigned char>(h[p]))) throw bad("shape is not a tuple of sizes");
    size_t d = 0;
    while (p < h.size() && std::isdigit(static_cast<unsigned char>(h[p]))) {
      d = d * 10 + size_t(h[p++] - '0');
      if (d > kMaxInputBytes) throw bad("a dimension is too large");
    }
    count *= d;
    if (count > kMaxInputBytes) throw bad("too many elements");
    a.shape.push_back(d);
    while (p < h.size() && h[p] == ' ') ++p;
    if (p < h.size() && h[p] == ',') ++p;
    if (a.shape.size() > 8) throw bad("more than 8 dimensions");
  }
  const size_t need = count * elem, have = b.size() - start - hlen;
  if (have != need)
    throw InputError(name + ": .npy data has " + std::to_string(have) + " bytes, its shape needs " + std::to_string(need));
  a.data.assign(b.begin() + long(start + hlen), b.end());
  return a;
}

// ---------------------------------------------------------------------------------------------
// By name

namespace {

Image image_from_npy(const NpyArray &a, const std::string &path) {
  const bool grey = a.shape.size() == 2 || (a.shape.size() == 3 && a.shape[2] == 1);
  const bool rgb = a.shape.size() == 3 && a.shape[2] == 3;
  if (a.dtype != "|u1" || !(grey || rgb))
    throw InputError(path + ": a frame in .npy is uint8 (|u1) of shape (H, W) or (H, W, 3), not " + a.dtype +
                     " of " + std::to_string(a.shape.size()) + " dimensions");
  if (a.shape[0] < 1 || a.shape[1] < 1 || a.shape[0] > size_t(kMaxFrameDim) || a.shape[1] > size_t(kMaxFrameDim))
    throw InputError(path + ": image " + size_name(a.shape[1], a.shape[0]) +
                     " outside 1.." + std::to_string(kMaxFrameDim) + " pixels a side");
  Image img(int(a.shape[1]), int(a.shape[0]), rgb ? 3 : 1);
  img.data = a.data;
  return img;
}

}  // namespace

Image read_image(const std::string &path) {
  const FileFormat f = format_of(path);
  switch (f) {
    case FileFormat::Pnm:
    case FileFormat::None: {
      Image img = read_pnm(path);
      const std::string ext = extension(path);
      if (ext == ".pgm" && img.channels != 1)
        throw InputError(path + ": a .pgm holds a grey image, this one is colour (P3/P6: name it .ppm)");
      if (ext == ".ppm" && img.channels != 3)
        throw InputError(path + ": a .ppm holds a colour image, this one is grey (P2/P5: name it .pgm)");
      return img;
    }
    case FileFormat::Png: return parse_png(read_file(path), path);
    case FileFormat::Npy: return image_from_npy(parse_npy(read_file(path), path), path);
    default: throw InputError(path + ": not an image (frames are .pgm, .ppm, .pnm, .png, .npy or .uyvy)");
  }
}

void write_image(const std::string &path, const Image &img) {
  check_output_name(path, OutputKind::Image);
  const FileFormat f = format_of(path);
  const std::string ext = extension(path);
  if (ext == ".pgm" && img.channels != 1)
    throw InputError(path + ": this output is a colour image: name it .ppm, .pnm or .png");
  if (ext == ".ppm" && img.channels != 3)
    throw InputError(path + ": this output is a grey image: name it .pgm, .pnm or .png");
  if (f == FileFormat::Png) {
    write_file_atomic(path, encode_png(img, path));
  } else if (f == FileFormat::Npy) {
    NpyArray a{"|u1", {size_t(img.height), size_t(img.width)}, img.data};
    if (img.channels != 1) a.shape.push_back(size_t(img.channels));
    write_file_atomic(path, encode_npy(a));
  } else {
    write_pnm(path, img);
  }
}

void write_flow(const std::string &path, const FlowField &flow) {
  check_output_name(path, OutputKind::Flow);
  if (format_of(path) != FileFormat::Npy) return write_flo(path, flow);
  const size_t n = size_t(flow.width) * flow.height;
  NpyArray a{"<f4", {size_t(flow.height), size_t(flow.width), 2}, std::vector<uint8_t>(n * 8)};
  for (size_t i = 0; i < n; ++i) {
    std::memcpy(&a.data[8 * i], &flow.u[i], 4);
    std::memcpy(&a.data[8 * i + 4], &flow.v[i], 4);
  }
  write_file_atomic(path, encode_npy(a));
}

void write_text_output(const std::string &path, const std::string &text) {
  check_output_name(path, OutputKind::Text);
  if (format_of(path) == FileFormat::Npy)
    throw InputError(path + ": this output is text; .npy writes a buffer (see --out-buffer)");
  write_file_atomic(path, text.data(), text.size());
}

}  // namespace bvb
