// The pipeline report's plots: what is drawn lands inside the plot frame, and trajectories keep
// their proportions (a square arena must not come out as a rectangle).
#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

#include "session/svg.h"

namespace bvb {
namespace {

struct Pt {
  double x, y;
};

// The points of every <polygon> or <polyline> element of `tag`.
std::vector<std::vector<Pt>> elements(const std::string &svg, const std::string &tag) {
  std::vector<std::vector<Pt>> out;
  const std::regex el("<" + tag + "[^>]*points=\"([^\"]*)\"");
  const std::regex pt("(-?[0-9.e+-]+),(-?[0-9.e+-]+)");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), el); it != std::sregex_iterator(); ++it) {
    const std::string pts = (*it)[1];
    std::vector<Pt> v;
    for (auto p = std::sregex_iterator(pts.begin(), pts.end(), pt); p != std::sregex_iterator(); ++p)
      v.push_back({std::stod((*p)[1]), std::stod((*p)[2])});
    out.push_back(v);
  }
  return out;
}

// The plot frame: the first <rect> with a stroke.
struct Frame {
  double x, y, w, h;
};
Frame plot_frame(const std::string &svg) {
  std::smatch m;
  const std::regex r("<rect x=\"([0-9.]+)\" y=\"([0-9.]+)\" width=\"([0-9.]+)\" height=\"([0-9.]+)\" fill=\"none\"");
  EXPECT_TRUE(std::regex_search(svg, m, r));
  return {std::stod(m[1]), std::stod(m[2]), std::stod(m[3]), std::stod(m[4])};
}

TEST(SvgPlot, ShapesAndSeriesFallInsideTheFrameWithAMargin) {
  // The path stays in a corner; the obstacle is far from it: both must be in view.
  Series path{"path", "#000", {1, 2, 3}, {1, 1.5, 2}};
  Shape box{"#f00", {50, 60, 60, 50}, {40, 40, 45, 45}};
  const std::string svg = svg_plot("t", "x", "y", {path}, true, {box});
  const Frame f = plot_frame(svg);
  const auto polys = elements(svg, "polygon"), lines = elements(svg, "polyline");
  ASSERT_EQ(polys.size(), 1u);
  ASSERT_EQ(lines.size(), 1u);
  for (const auto &el : {polys[0], lines[0]})
    for (const Pt &p : el) {
      EXPECT_GT(p.x, f.x);
      EXPECT_LT(p.x, f.x + f.w);
      EXPECT_GT(p.y, f.y);
      EXPECT_LT(p.y, f.y + f.h);
    }
}

TEST(SvgPlot, EqualAspectKeepsASquareSquare) {
  Series path{"path", "#000", {0, 10}, {0, 0}};
  Shape square{"#00f", {0, 10, 10, 0}, {0, 0, 10, 10}};
  const auto p = elements(svg_plot("t", "x", "y", {path}, true, {square}), "polygon");
  ASSERT_EQ(p.size(), 1u);
  ASSERT_EQ(p[0].size(), 4u);
  const double w = p[0][1].x - p[0][0].x, h = p[0][1].y - p[0][2].y;  // y grows downwards
  EXPECT_GT(w, 50);
  EXPECT_NEAR(w, h, 0.01);  // coordinates are written with 6 significant digits
}

TEST(SvgPlot, WithoutEqualAspectEachAxisFillsTheFrame) {
  Series s{"cycles", "#000", {0, 1000}, {0, 5e6}};
  const std::string svg = svg_plot("t", "frame", "cycles", {s}, false);
  const Frame f = plot_frame(svg);
  const auto l = elements(svg, "polyline");
  ASSERT_EQ(l.size(), 1u);
  // Apart from the margin, the series spans the frame in both directions.
  EXPECT_GT(l[0][1].x - l[0][0].x, 0.9 * f.w);
  EXPECT_GT(l[0][0].y - l[0][1].y, 0.9 * f.h);
  EXPECT_EQ(svg.find("-0<"), std::string::npos);  // no tick labelled -0
}

}  // namespace
}  // namespace bvb
