// A small software rasterizer for previews: orthographic projection, a depth buffer, Lambert
// plus ambient lighting, an alpha test for leaf cards and supersampling for anti-aliasing.
// No GPU, no window: it works headless.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "core/vec3.h"

namespace ramus::preview {

struct Rgb {
  float r = 0, g = 0, b = 0;
};

// An RGB image with a depth buffer, rows top to bottom.
class Raster {
 public:
  Raster(int width, int height, Rgb background);
  int width() const { return w_; }
  int height() const { return h_; }
  const Rgb& at(int x, int y) const { return colour_[std::size_t(y) * w_ + x]; }
  float depth(int x, int y) const { return depth_[std::size_t(y) * w_ + x]; }

  // A triangle whose vertices are already in pixel coordinates (x right, y down) with a depth
  // (smaller is nearer). `shade` gives the colour at barycentric (b0, b1, b2) or returns false
  // to discard the sample (alpha test). Pixel centres at (x + 0.5, y + 0.5) are covered when
  // inside or on a top-left edge, so triangles sharing an edge never double-cover a pixel.
  using Shader = std::function<bool(float b0, float b1, float b2, Rgb& out)>;
  void triangle(const std::array<Vec3f, 3>& v, const Shader& shade);

  // A round dot of `radius` pixels about (x, y) at depth `z` (a point of a scan), depth-tested
  // like a triangle: the pixels whose centres lie within the radius.
  void dot(float x, float y, float z, float radius, const Rgb& colour);

  // Box-filtered downsampling by an integer factor, to 8-bit RGB.
  std::vector<std::uint8_t> resolve(int factor) const;

 private:
  int w_, h_;
  std::vector<Rgb> colour_;
  std::vector<float> depth_;
};

}  // namespace ramus::preview
