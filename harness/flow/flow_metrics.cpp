#include "flow_metrics.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "io.h"
#include "names.h"

namespace bvb {

namespace {

void check_same_size(const FlowField &a, const FlowField &b, const char *what) {
  if (a.width != b.width || a.height != b.height)
    throw InputError(std::string(what) + ": flow sizes differ (" + size_name(a.width, a.height) + " vs " + size_name(b.width, b.height) + ")");
}

}  // namespace

FlowErrors flow_errors(const FlowField &flow, const FlowField &truth) {
  check_same_size(flow, truth, "flow_errors");
  const double kDeg = 180.0 / 3.14159265358979323846;
  double sum_epe = 0, sum_ae = 0;
  long long n = 0;
  for (size_t p = 0; p < truth.u.size(); ++p) {
    const float ug = truth.u[p], vg = truth.v[p];
    if (FlowField::unknown(ug) || FlowField::unknown(vg)) continue;
    const double u = flow.u[p], v = flow.v[p];
    if (FlowField::unknown(flow.u[p]) || FlowField::unknown(flow.v[p]))
      throw InputError("flow_errors: estimated flow has an unknown vector at pixel " +
                       std::to_string(p % size_t(truth.width)) + "," +
                       std::to_string(p / size_t(truth.width)));
    const double du = u - ug, dv = v - vg;
    sum_epe += std::sqrt(du * du + dv * dv);
    const double c = (u * ug + v * vg + 1.0) /
                     std::sqrt((u * u + v * v + 1.0) * (double(ug) * ug + double(vg) * vg + 1.0));
    sum_ae += std::acos(std::clamp(c, -1.0, 1.0)) * kDeg;
    ++n;
  }
  FlowErrors e;
  e.valid = n;
  if (n > 0) {
    e.epe = sum_epe / double(n);
    e.ae = sum_ae / double(n);
  }
  return e;
}

FlowDistance flow_distance(const FlowField &a, const FlowField &b) {
  check_same_size(a, b, "flow_distance");
  FlowDistance d;
  if (a.u.empty()) return d;
  double sum = 0;
  for (size_t p = 0; p < a.u.size(); ++p) {
    const double du = double(a.u[p]) - b.u[p], dv = double(a.v[p]) - b.v[p];
    const double e = std::sqrt(du * du + dv * dv);
    sum += e;
    d.max = std::max(d.max, e);
  }
  d.mean = sum / double(a.u.size());
  return d;
}

FlowField flow_from_fixed(const int16_t *uv, int width, int height, int stride_bytes,
                          int frac_bits) {
  if (width < 0 || height < 0 || stride_bytes < 4 * width || frac_bits < 0 || frac_bits > 15)
    throw InputError("flow_from_fixed: bad size, stride or Q format");
  FlowField f(width, height);
  const double scale = std::ldexp(1.0, -frac_bits);
  for (int y = 0; y < height; ++y) {
    const int16_t *row = reinterpret_cast<const int16_t *>(reinterpret_cast<const uint8_t *>(uv) +
                                                           size_t(y) * size_t(stride_bytes));
    for (int x = 0; x < width; ++x) {
      f.u[size_t(y) * width + x] = float(row[2 * x] * scale);
      f.v[size_t(y) * width + x] = float(row[2 * x + 1] * scale);
    }
  }
  return f;
}

}  // namespace bvb
