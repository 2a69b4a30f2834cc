#include "svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace bvb {

namespace {

std::string esc(const std::string &s) {
  std::string o;
  for (char c : s) {
    if (c == '<') o += "&lt;";
    else if (c == '>') o += "&gt;";
    else if (c == '&') o += "&amp;";
    else o += c;
  }
  return o;
}

double nice_step(double range) {
  if (range <= 0) return 1;
  double raw = range / 6, mag = std::pow(10, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (raw <= m * mag) return m * mag;
  return 10 * mag;
}

std::string num(double v) {
  char b[32];
  if (std::fabs(v) < 1e-9) v = 0;  // a tick computed as -0 reads as zero
  if (std::fabs(v) >= 1e6) std::snprintf(b, sizeof b, "%.3g", v);
  else std::snprintf(b, sizeof b, "%g", std::round(v * 1000) / 1000);
  return b;
}

}  // namespace

std::string svg_plot(const std::string &title, const std::string &xlabel, const std::string &ylabel,
                     const std::vector<Series> &series, bool equal_aspect,
                     const std::vector<Shape> &shapes) {
  const double W = 720, H = 480, L = 80, R = 20, T = 40, B = 60;
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  auto extend = [&](const std::vector<double> &xs, const std::vector<double> &ys) {
    for (size_t i = 0; i < xs.size() && i < ys.size(); ++i) {
      if (!std::isfinite(xs[i]) || !std::isfinite(ys[i])) continue;
      x0 = std::min(x0, xs[i]), x1 = std::max(x1, xs[i]);
      y0 = std::min(y0, ys[i]), y1 = std::max(y1, ys[i]);
    }
  };
  for (const auto &s : series) extend(s.x, s.y);
  for (const auto &s : shapes) extend(s.x, s.y);
  if (x0 > x1) x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  if (x1 - x0 < 1e-9) x0 -= 1, x1 += 1;
  if (y1 - y0 < 1e-9) y0 -= 1, y1 += 1;
  const double mx = 0.03 * (x1 - x0), my = 0.03 * (y1 - y0);
  x0 -= mx, x1 += mx, y0 -= my, y1 += my;
  const double pw = W - L - R, ph = H - T - B;
  double sx = pw / (x1 - x0), sy = ph / (y1 - y0);
  if (equal_aspect) {  // the data centred in the axis that gets wider
    const double sc = std::min(sx, sy), cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
    x0 = cx - pw / sc / 2, x1 = cx + pw / sc / 2;
    y0 = cy - ph / sc / 2, y1 = cy + ph / sc / 2;
    sx = sy = sc;
  }
  auto X = [&](double v) { return L + (v - x0) * sx; };
  auto Y = [&](double v) { return T + ph - (v - y0) * sy; };
  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    << "<text x=\"" << W / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">" << esc(title) << "</text>\n";
  o << "<rect x=\"" << L << "\" y=\"" << T << "\" width=\"" << pw << "\" height=\"" << ph
    << "\" fill=\"none\" stroke=\"#888\"/>\n";
  const double xs = nice_step(x1 - x0), ys = nice_step(y1 - y0);
  for (double v = std::ceil(x0 / xs) * xs; v <= x1 + 1e-9; v += xs)
    o << "<line x1=\"" << X(v) << "\" y1=\"" << T << "\" x2=\"" << X(v) << "\" y2=\"" << T + ph
      << "\" stroke=\"#eee\"/><text x=\"" << X(v) << "\" y=\"" << T + ph + 16
      << "\" text-anchor=\"middle\">" << num(v) << "</text>\n";
  for (double v = std::ceil(y0 / ys) * ys; v <= y1 + 1e-9; v += ys)
    o << "<line x1=\"" << L << "\" y1=\"" << Y(v) << "\" x2=\"" << L + pw << "\" y2=\"" << Y(v)
      << "\" stroke=\"#eee\"/><text x=\"" << L - 6 << "\" y=\"" << Y(v) + 4
      << "\" text-anchor=\"end\">" << num(v) << "</text>\n";
  o << "<text x=\"" << L + pw / 2 << "\" y=\"" << H - 16 << "\" text-anchor=\"middle\">" << esc(xlabel)
    << "</text>\n<text x=\"18\" y=\"" << T + ph / 2 << "\" text-anchor=\"middle\" transform=\"rotate(-90 18 "
    << T + ph / 2 << ")\">" << esc(ylabel) << "</text>\n";
  for (const auto &s : shapes) {
    o << "<polygon fill=\"" << s.fill << "\" stroke=\"#555\" stroke-width=\"0.5\" points=\"";
    for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) o << X(s.x[i]) << "," << Y(s.y[i]) << " ";
    o << "\"/>\n";
  }
  for (const auto &s : series) {
    o << "<polyline fill=\"none\" stroke=\"" << s.colour << "\" stroke-width=\"2\" points=\"";
    for (size_t i = 0; i < s.x.size(); ++i)
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i])) o << X(s.x[i]) << "," << Y(s.y[i]) << " ";
    o << "\"/>\n";
  }
  // The legend last, on a white ground: a trajectory or an obstacle may run under it.
  size_t longest = 0;
  for (const auto &s : series) longest = std::max(longest, s.label.size());
  o << "<rect x=\"" << L + 6 << "\" y=\"" << T + 6 << "\" width=\"" << 44 + 7 * longest << "\" height=\""
    << 18 * series.size() + 4 << "\" fill=\"white\" fill-opacity=\"0.85\"/>\n";
  int li = 0;
  for (const auto &s : series) {
    const double ly = T + 16 + 18 * li++;
    o << "<line x1=\"" << L + 12 << "\" y1=\"" << ly << "\" x2=\"" << L + 36 << "\" y2=\"" << ly
      << "\" stroke=\"" << s.colour << "\" stroke-width=\"3\"/><text x=\"" << L + 42 << "\" y=\"" << ly + 4
      << "\">" << esc(s.label) << "</text>\n";
  }
  o << "</svg>\n";
  return o.str();
}

}  // namespace bvb
