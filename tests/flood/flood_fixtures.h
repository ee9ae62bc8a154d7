// Point clouds with known axes for the flood-fill tests: bark (surface) or solid cylinders.
#pragma once

#include <cmath>

#include "core/point_cloud.h"
#include "core/rng.h"
#include "core/skeleton.h"

namespace ramus::test {

// Adds `count` points of a cylinder from a to b of radius r: on its surface, or uniform in its
// volume when `solid`.
inline void add_cylinder(PointCloud& c, Vec3 a, Vec3 b, double r, int count, bool solid,
                         std::uint64_t seed) {
  Rng rng(seed);
  const Vec3 h = normalized(b - a);
  const Vec3 ref = std::abs(h.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
  const Vec3 u = normalized(cross(ref, h)), v = cross(h, u);
  const double len = length(b - a);
  for (int i = 0; i < count; ++i) {
    const double t = rng.uniform(0, len), phi = rng.uniform(0, 2 * M_PI);
    const double rho = solid ? r * std::sqrt(rng.uniform01()) : r;
    const Vec3 p = a + h * t + u * (rho * std::cos(phi)) + v * (rho * std::sin(phi));
    c.positions.push_back(Vec3f(p));
  }
}

// Angle in degrees between two directions (sign ignored when `unsigned_axis`).
inline double angle_deg(Vec3 a, Vec3 b) {
  const double c = dot(normalized(a), normalized(b));
  return std::acos(std::max(-1.0, std::min(1.0, c))) * 180 / M_PI;
}

// Distance from p to the segment a-b.
inline double segment_distance(Vec3 p, Vec3 a, Vec3 b) {
  const Vec3 d = b - a;
  const double t = std::max(0.0, std::min(1.0, dot(p - a, d) / std::max(dot(d, d), 1e-300)));
  return length(p - (a + d * t));
}

}  // namespace ramus::test
