// Minimal SVG line plots for pipeline reports: trajectories and cycles per frame.
#pragma once

#include <string>
#include <vector>

namespace bvb {

struct Series {
  std::string label;
  std::string colour;
  std::vector<double> x, y;
};

// A filled outline drawn under the series (an obstacle of the arena a trajectory runs in).
struct Shape {
  std::string fill;
  std::vector<double> x, y;
};

// A plot with axes, ticks, a legend; equal_aspect for trajectories. The ranges take in the
// series and the shapes, with a margin so that nothing is drawn on the frame.
std::string svg_plot(const std::string &title, const std::string &xlabel, const std::string &ylabel,
                     const std::vector<Series> &series, bool equal_aspect,
                     const std::vector<Shape> &shapes = {});

}  // namespace bvb
