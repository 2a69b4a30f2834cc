#include "family.h"

#include <cstdlib>
#include <map>

#include "bvb/hornschunck.h"

#include "io.h"
#include "names.h"

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
  // The keys asked for are the ones this kernel knows: listing them saves a trip to the source.
  std::string known;
  for (const auto &k : used_) known += (known.empty() ? "" : ", ") + k;
  for (const auto &kv : values_)
    if (!used_.count(kv.first))
      throw InputError("unknown parameter '" + kv.first + "' for this kernel (" +
                       (known.empty() ? std::string("it takes none") : "it takes " + known) + ")");
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

const SizeRule *bench_size_rule(const std::string &kernel) {
  static const std::map<std::string, SizeRule> rules = {
      {"add_sat_u8", {1, 1, false}},
      {"blobs_uyvy", {2, 1, true}},
      {"canny", {3, 3, false}},  // on a Sobel gradient (3x3 at least)
      {"uyvy_to_grey", {2, 1, true}},
      {"uyvy_to_rgb24", {2, 1, true}},
      {"erode3x3_u8", {1, 1, false}},
      {"dilate3x3_u8", {1, 1, false}},
      {"scanline_profile_u8", {1, 2, false}},  // a band of half the height, at least one row
      {"scanline_shift_u8", {2, 1, false}},    // minimum overlap half the width, at least 1
      {"sobel3x3_u8", {3, 3, false}},
      {"sobel3x3_s16", {3, 3, false}},
      {"harris_response", {5, 5, false}},
      {"harris_nms", {5, 5, false}},     // on harris_response's output
      {"harris_select", {5, 5, false}},  // on harris_nms's output
      {"lk_pyramid", {1, 1, false}},
      {"lk_track", {5, 5, false}},  // tracks Harris corners
      // 32 points whose 11x11 templates and +-8 searches lie inside: 2 * (5 + 8) + 1.
      {"ncc_match", {27, 27, false}},
      {"ncc_scoremap", {27, 27, false}},
      {"region_grow", {1, 1, false}},
      {"free_space", {1, 1, false}},
      {"hs_prepare", {BVB_HS_MIN_DIM, BVB_HS_MIN_DIM, false}},
      {"hs_iterate", {BVB_HS_MIN_DIM, BVB_HS_MIN_DIM, false}},
      {"hs_iterate_n", {BVB_HS_MIN_DIM, BVB_HS_MIN_DIM, false}},
      {"hornschunck", {BVB_HS_MIN_DIM, BVB_HS_MIN_DIM, false}},
      // Whole-pipeline frames: the avoidance pipelines bench only at 160x120 and 320x240 and
      // skip other sizes; odometry renders a UYVY scene at any even size from 16x16.
      {"pipe_seg_avoid", {1, 1, false}},
      {"pipe_flow_avoid", {1, 1, false}},
      {"pipe_odometry", {16, 16, true}},
      {"dma_copy_u8", {1, 1, false}},
  };
  auto it = rules.find(kernel);
  return it == rules.end() ? nullptr : &it->second;
}

std::string bench_size_problem(const std::string &kernel, int w, int h) {
  const SizeRule *r = bench_size_rule(kernel);
  if (!r) return "";
  const std::string got = size_name(w, h);
  if (w < r->min_w || h < r->min_h || (r->even_width && (w & 1)))
    return kernel + " needs at least " + size_name(r->min_w, r->min_h) +
           (r->even_width ? " and an even width" : "") + ", not " + got;
  return "";
}

Image read_frame(const std::string &path, int raw_w, int raw_h) {
  if (format_of(path) == FileFormat::Uyvy) {
    if (raw_w <= 0 || raw_h <= 0) throw InputError(path + ": raw UYVY input needs --size WxH");
    auto bytes = read_uyvy(path, raw_w, raw_h);
    Image img(raw_w, raw_h);
    for (size_t i = 0; i < img.data.size(); ++i) img.data[i] = bytes[2 * i + 1];  // the Y bytes
    return img;
  }
  return read_image(path);
}

Image read_input(const RunRequest &req, size_t i) {
  if (i >= req.inputs.size()) throw InputError(req.kernel + " needs " + std::to_string(i + 1) + " --in frames");
  const std::string &path = req.inputs[i];
  Image img = read_frame(path, req.raw_width, req.raw_height);
  if (img.channels == 1) return img;
  // Never greyed silently: a colour frame may be a mistake (the wrong file, a kernel that was
  // meant to see colour), so converting is the user's explicit choice.
  if (!req.grey_from_colour)
    throw InputError(path + ": a colour image, and " + req.kernel +
                     " takes grey frames (.pgm, a grey .png, a uint8 HxW .npy, or .uyvy's Y plane); "
                     "--grey converts colour with BT.601 luma");
  Image g(img.width, img.height);
  for (size_t k = 0; k < g.data.size(); ++k) {
    const uint8_t *p = &img.data[3 * k];
    g.data[k] = uint8_t((77 * p[0] + 150 * p[1] + 29 * p[2] + 128) >> 8);
  }
  return g;
}

NpyArray npy_of_buffer(const Buffer &b, const std::vector<uint8_t> &data) {
  const View &v = b.view;
  const size_t elem = size_t(v.elem);
  NpyArray a;
  a.dtype = npy_int_dtype(v.elem, v.is_signed);
  if (v.width <= 0) {
    a.shape = {data.size() / elem};
    a.data.assign(data.begin(), data.begin() + long(a.shape[0] * elem));
    return a;
  }
  const size_t cols = size_t(v.width), rows = size_t(v.height), stride = size_t(v.stride > 0 ? v.stride : v.width);
  if (((rows - 1) * stride + cols) * elem > data.size())
    throw std::logic_error("buffer '" + b.name + "' is smaller than its view");
  a.shape = {rows, cols};
  if (v.channels > 1 && cols % size_t(v.channels) == 0) a.shape = {rows, cols / size_t(v.channels), size_t(v.channels)};
  a.data.reserve(rows * cols * elem);
  for (size_t y = 0; y < rows; ++y) {
    const auto row = data.begin() + long(y * stride * elem);
    a.data.insert(a.data.end(), row, row + long(cols * elem));
  }
  return a;
}

}  // namespace bvb
