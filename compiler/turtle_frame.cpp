#include "compiler/turtle_frame.h"

#include <cmath>

#include "grammar/builtins.h"

namespace ramus {

namespace {

constexpr double kRad = kPi / 180.0;

// Rodrigues' rotation of v about unit axis k by `angle` radians.
Vec3 rotate_about(const Vec3& v, const Vec3& k, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return v * c + cross(k, v) * s + k * (dot(k, v) * (1 - c));
}

}  // namespace

void TurtleFrame::orthonormalize() {
  h = normalized(h);
  l = normalized(l - h * dot(l, h), Vec3{-1, 0, 0});
  u = cross(h, l);
}

void rotate_pair(Vec3& a, Vec3& b, double degrees) {
  const double c = std::cos(degrees * kRad), s = std::sin(degrees * kRad);
  const Vec3 a2 = a * c + b * s;
  b = b * c - a * s;
  a = a2;
}

void TurtleFrame::bend(const Vec3& tropism, double elasticity) {
  if (elasticity == 0) return;
  const Vec3 axis = cross(h, tropism);
  const double len = length(axis);
  if (len < 1e-12) return;
  const Vec3 k = axis / len;
  const double alpha = elasticity * len;
  h = rotate_about(h, k, alpha);
  l = rotate_about(l, k, alpha);
  orthonormalize();
}

void TurtleFrame::level() {
  const Vec3 v{0, 0, 1};
  const Vec3 left = cross(v, h);
  if (length(left) < 1e-12) return;
  l = normalized(left);
  u = cross(h, l);
}

}  // namespace ramus
