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

// A plot with axes, ticks, a legend; equal_aspect for trajectories.
std::string svg_plot(const std::string &title, const std::string &xlabel, const std::string &ylabel,
                     const std::vector<Series> &series, bool equal_aspect);

}  // namespace bvb
