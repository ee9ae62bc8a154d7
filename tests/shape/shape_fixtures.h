// Small skeletons and clouds the shape tests build by hand: poles, chains along a direction,
// bark rings.
#pragma once

#include <cmath>
#include <vector>

#include "core/point_cloud.h"
#include "core/skeleton.h"

namespace shape_test {

using ramus::kNoParent;
using ramus::PointCloud;
using ramus::Skeleton;
using ramus::SkeletonNode;
using ramus::Vec3;
using ramus::Vec3f;

constexpr double kPi = 3.14159265358979323846;

// Appends a chain of `pieces` equal segments from `from` to `to`; the first node hangs from
// `parent` (kNoParent: a new root). Returns the last node.
inline std::uint32_t chain(Skeleton& s, Vec3 from, Vec3 to, int pieces,
                           std::uint32_t parent = kNoParent) {
  std::uint32_t prev = parent;
  if (prev == kNoParent) {
    SkeletonNode root;
    root.position = from;
    prev = s.add(root);
  }
  for (int k = 1; k <= pieces; ++k) {
    SkeletonNode n;
    n.position = from + (to - from) * (double(k) / pieces);
    n.parent = prev;
    n.radius = 0.05;
    prev = s.add(n);
  }
  return prev;
}

// A unit vector `degrees` from vertical towards azimuth `azimuth_degrees`.
inline Vec3 tilted(double degrees, double azimuth_degrees) {
  const double t = degrees * kPi / 180, a = azimuth_degrees * kPi / 180;
  return {std::sin(t) * std::cos(a), std::sin(t) * std::sin(a), std::cos(t)};
}

inline PointCloud cloud_of(const std::vector<Vec3>& points, Vec3 offset = {}) {
  PointCloud c;
  c.offset = offset;
  for (const Vec3& p : points) c.positions.push_back(Vec3f(p - offset));
  return c;
}

}  // namespace shape_test
