// Host-side image and flow-field containers shared by the harness, the scene generator and the
// accuracy tools. Pixels are packed row-major with no padding; strides appear only when a buffer
// is laid out for a kernel call.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace bvb {

// 8-bit image with 1 (grey) or 3 (RGB) interleaved channels.
struct Image {
  int width = 0;
  int height = 0;
  int channels = 1;
  std::vector<uint8_t> data;

  Image() = default;
  Image(int w, int h, int c = 1, uint8_t fill = 0)
      : width(w), height(h), channels(c), data(size_t(w) * size_t(h) * size_t(c), fill) {}
  uint8_t &at(int x, int y, int c = 0) { return data[(size_t(y) * width + x) * channels + c]; }
  uint8_t at(int x, int y, int c = 0) const { return data[(size_t(y) * width + x) * channels + c]; }
};

// Dense optical flow in pixels; u to the right, v downwards (Middlebury convention). Unknown
// vectors hold values above 1e9, as in .flo files.
struct FlowField {
  int width = 0;
  int height = 0;
  std::vector<float> u, v;

  FlowField() = default;
  FlowField(int w, int h) : width(w), height(h), u(size_t(w) * h, 0.f), v(size_t(w) * h, 0.f) {}
  static bool unknown(float a) { return !(a < 1e9f && a > -1e9f); }
};

}  // namespace bvb
