// Half-space triangle rasterization (Pineda, "A parallel algorithm for polygon rasterization",
// SIGGRAPH 1988) with the top-left fill rule of Direct3D/OpenGL.
#include "backends/preview/raster.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ramus::preview {
namespace {

double edge(const Vec3f& a, const Vec3f& b, double px, double py) {
  return (double(b.x) - a.x) * (py - a.y) - (double(b.y) - a.y) * (px - a.x);
}

// Top or left edge for a triangle wound so that its area is positive (y down).
bool top_left(const Vec3f& a, const Vec3f& b) {
  const double dx = double(b.x) - a.x, dy = double(b.y) - a.y;
  return (dy == 0 && dx < 0) || dy > 0;
}

}  // namespace

Raster::Raster(int width, int height, Rgb background)
    : w_(std::max(width, 1)),
      h_(std::max(height, 1)),
      colour_(std::size_t(w_) * h_, background),
      depth_(std::size_t(w_) * h_, std::numeric_limits<float>::infinity()) {}

void Raster::triangle(const std::array<Vec3f, 3>& in, const Shader& shade) {
  std::array<Vec3f, 3> v = in;
  double area = edge(v[0], v[1], v[2].x, v[2].y);
  if (!std::isfinite(area) || area == 0) return;
  if (area < 0) {  // rasterize both windings; the barycentrics follow the swap
    std::swap(v[1], v[2]);
    area = -area;
  }
  const bool swapped = edge(in[0], in[1], in[2].x, in[2].y) < 0;
  const int x0 = std::max(0, int(std::floor(std::min({v[0].x, v[1].x, v[2].x}))));
  const int x1 = std::min(w_ - 1, int(std::ceil(std::max({v[0].x, v[1].x, v[2].x}))));
  const int y0 = std::max(0, int(std::floor(std::min({v[0].y, v[1].y, v[2].y}))));
  const int y1 = std::min(h_ - 1, int(std::ceil(std::max({v[0].y, v[1].y, v[2].y}))));
  const bool tl0 = top_left(v[1], v[2]), tl1 = top_left(v[2], v[0]), tl2 = top_left(v[0], v[1]);
  for (int y = y0; y <= y1; ++y) {
    const double py = y + 0.5;
    for (int x = x0; x <= x1; ++x) {
      const double px = x + 0.5;
      const double w0 = edge(v[1], v[2], px, py), w1 = edge(v[2], v[0], px, py),
                   w2 = edge(v[0], v[1], px, py);
      if (w0 < 0 || w1 < 0 || w2 < 0) continue;
      if ((w0 == 0 && !tl0) || (w1 == 0 && !tl1) || (w2 == 0 && !tl2)) continue;
      float b0 = float(w0 / area), b1 = float(w1 / area), b2 = float(w2 / area);
      const float z = b0 * v[0].z + b1 * v[1].z + b2 * v[2].z;
      float& d = depth_[std::size_t(y) * w_ + x];
      if (z >= d) continue;
      if (swapped) std::swap(b1, b2);  // back to the caller's vertex order
      Rgb c;
      if (!shade(b0, b1, b2, c)) continue;
      d = z;
      colour_[std::size_t(y) * w_ + x] = c;
    }
  }
}

void Raster::dot(float x, float y, float z, float radius, const Rgb& colour) {
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) return;
  const int x0 = std::max(0, int(std::floor(x - radius)));
  const int x1 = std::min(w_ - 1, int(std::ceil(x + radius)));
  const int y0 = std::max(0, int(std::floor(y - radius)));
  const int y1 = std::min(h_ - 1, int(std::ceil(y + radius)));
  const double r2 = double(radius) * radius;
  for (int py = y0; py <= y1; ++py) {
    for (int px = x0; px <= x1; ++px) {
      const double dx = px + 0.5 - x, dy = py + 0.5 - y;
      if (dx * dx + dy * dy > r2) continue;
      float& d = depth_[std::size_t(py) * w_ + px];
      if (z >= d) continue;
      d = z;
      colour_[std::size_t(py) * w_ + px] = colour;
    }
  }
}

std::vector<std::uint8_t> Raster::resolve(int f) const {
  f = std::max(f, 1);
  const int ow = w_ / f, oh = h_ / f;
  std::vector<std::uint8_t> out(std::size_t(ow) * oh * 3);
  const float norm = 1.0f / float(f * f);
  for (int y = 0; y < oh; ++y) {
    for (int x = 0; x < ow; ++x) {
      Rgb sum;
      for (int j = 0; j < f; ++j) {
        for (int i = 0; i < f; ++i) {
          const Rgb& c = at(x * f + i, y * f + j);
          sum.r += c.r;
          sum.g += c.g;
          sum.b += c.b;
        }
      }
      std::uint8_t* p = &out[(std::size_t(y) * ow + x) * 3];
      p[0] = std::uint8_t(std::lround(std::clamp(sum.r * norm, 0.0f, 1.0f) * 255));
      p[1] = std::uint8_t(std::lround(std::clamp(sum.g * norm, 0.0f, 1.0f) * 255));
      p[2] = std::uint8_t(std::lround(std::clamp(sum.b * norm, 0.0f, 1.0f) * 255));
    }
  }
  return out;
}

}  // namespace ramus::preview
