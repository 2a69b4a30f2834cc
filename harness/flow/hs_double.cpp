#include "hs_double.h"

#include <algorithm>
#include <string>

#include "io.h"
#include "names.h"

namespace bvb {

namespace {

void check_frames(const Image &a, const Image &b) {
  if (a.channels != 1 || b.channels != 1) throw InputError("Horn-Schunck: frames must be grey");
  if (a.width != b.width || a.height != b.height)
    throw InputError("Horn-Schunck: frame sizes differ (" + size_name(a.width, a.height) + " vs " + size_name(b.width, b.height) + ")");
  if (a.width < 1 || a.height < 1) throw InputError("Horn-Schunck: empty frame");
}

}  // namespace

HsDerivatives hs_derivatives_double(const Image &f1, const Image &f2) {
  check_frames(f1, f2);
  const int w = f1.width, h = f1.height;
  HsDerivatives d;
  d.width = w;
  d.height = h;
  d.ex.resize(size_t(w) * h);
  d.ey.resize(size_t(w) * h);
  d.et.resize(size_t(w) * h);
  for (int y = 0; y < h; ++y) {
    const int y1 = std::min(y + 1, h - 1);
    for (int x = 0; x < w; ++x) {
      const int x1 = std::min(x + 1, w - 1);
      // E[k][i][j]: frame k, row offset i, column offset j.
      double e[2][2][2];
      for (int k = 0; k < 2; ++k) {
        const Image &f = k ? f2 : f1;
        e[k][0][0] = f.at(x, y);
        e[k][0][1] = f.at(x1, y);
        e[k][1][0] = f.at(x, y1);
        e[k][1][1] = f.at(x1, y1);
      }
      double ex = 0, ey = 0, et = 0;
      for (int k = 0; k < 2; ++k)
        for (int i = 0; i < 2; ++i) ex += e[k][i][1] - e[k][i][0];
      for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j) ey += e[k][1][j] - e[k][0][j];
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) et += e[1][i][j] - e[0][i][j];
      const size_t p = size_t(y) * w + x;
      d.ex[p] = ex / 4;
      d.ey[p] = ey / 4;
      d.et[p] = et / 4;
    }
  }
  return d;
}

FlowField hs_flow_double(const Image &f1, const Image &f2, double alpha, int iterations) {
  if (iterations < 0) throw InputError("Horn-Schunck: negative iteration count");
  const HsDerivatives d = hs_derivatives_double(f1, f2);
  const int w = d.width, h = d.height;
  const size_t n = size_t(w) * h;
  const double a2 = alpha * alpha;
  std::vector<double> denom(n);
  for (size_t p = 0; p < n; ++p) denom[p] = a2 + d.ex[p] * d.ex[p] + d.ey[p] * d.ey[p];

  std::vector<double> u(n, 0.0), v(n, 0.0), un(n), vn(n);
  for (int it = 0; it < iterations; ++it) {
    for (int y = 0; y < h; ++y) {
      const int ym = std::max(y - 1, 0), yp = std::min(y + 1, h - 1);
      for (int x = 0; x < w; ++x) {
        const int xm = std::max(x - 1, 0), xp = std::min(x + 1, w - 1);
        auto avg = [&](const std::vector<double> &f) {
          auto at = [&](int xx, int yy) { return f[size_t(yy) * w + xx]; };
          const double edge = at(xm, y) + at(xp, y) + at(x, ym) + at(x, yp);
          const double diag = at(xm, ym) + at(xp, ym) + at(xm, yp) + at(xp, yp);
          return edge / 6.0 + diag / 12.0;
        };
        const size_t p = size_t(y) * w + x;
        const double ub = avg(u), vb = avg(v);
        const double t = (d.ex[p] * ub + d.ey[p] * vb + d.et[p]) / denom[p];
        un[p] = ub - d.ex[p] * t;
        vn[p] = vb - d.ey[p] * t;
      }
    }
    u.swap(un);
    v.swap(vn);
  }

  FlowField flow(w, h);
  for (size_t p = 0; p < n; ++p) {
    flow.u[p] = float(u[p]);
    flow.v[p] = float(v[p]);
  }
  return flow;
}

}  // namespace bvb
