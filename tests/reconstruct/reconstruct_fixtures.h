// Synthetic trees with known skeletons and clouds sampled on their bark, for the reconstruction
// tests: everything is seeded, so a failing case reproduces exactly.
#pragma once

#include <cmath>

#include "core/point_cloud.h"
#include "core/rng.h"
#include "core/skeleton.h"

namespace ramus::test {

// A sympodial-ish tree: a trunk with `levels` levels of lateral branches, gently curving.
inline void grow_branch(Skeleton& s, Rng& rng, std::uint32_t from, Vec3 dir, double length,
                        double radius, int levels, double step) {
  const int segments = std::max(2, int(length / step));
  std::uint32_t prev = from;
  for (int i = 1; i <= segments; ++i) {
    dir = normalized(dir + Vec3{rng.uniform(-0.08, 0.08), rng.uniform(-0.08, 0.08), 0.02});
    SkeletonNode n;
    n.position = s.nodes[prev].position + dir * (length / segments);
    n.radius = radius * (1.0 - 0.5 * double(i) / segments);
    n.parent = prev;
    prev = s.add(n);
    if (levels > 0 && i >= segments / 4 && i < segments && i % 3 == 0) {
      const double az = rng.uniform(0, 2 * M_PI);
      Vec3 side{std::cos(az), std::sin(az), 0.0};
      Vec3 child = normalized(side + dir * 0.6);
      grow_branch(s, rng, prev, child, length * 0.45, n.radius * 0.55, levels - 1, step);
    }
  }
}

inline Skeleton synthetic_tree(std::uint64_t seed, Vec3 base, double height = 6.0, int levels = 2,
                               double base_radius = 0) {
  Rng rng(seed);
  Skeleton s;
  SkeletonNode root;
  root.position = base;
  root.radius = base_radius > 0 ? base_radius : height * 0.025;
  s.add(root);
  grow_branch(s, rng, 0, {0, 0, 1}, height, root.radius, levels, height / 24);
  return s;
}

// A thick tree for the centre-line harness (issue 19): the trunk tapers from `base_radius` to
// half of it, limbs start at 0.55 x the trunk's radius where they leave it, their branches at
// 0.55 x the limb's; with base_radius 0.6 the radii span about 5-60 cm.
inline Skeleton thick_tree(std::uint64_t seed, double height, double base_radius) {
  return synthetic_tree(seed, {0, 0, 0}, height, 2, base_radius);
}

// Points on the surface of each segment's cylinder: `density` points per unit area plus
// Gaussian noise of standard deviation `noise` along the surface normal.
inline void sample_bark(const Skeleton& s, double density, double noise, Rng& rng,
                        PointCloud& cloud) {
  for (const SkeletonNode& n : s.nodes) {
    if (n.parent == kNoParent) continue;
    const SkeletonNode& p = s.nodes[n.parent];
    const Vec3 axis = n.position - p.position;
    const double len = length(axis);
    const Vec3 d = axis / len;
    const Vec3 e1 = normalized(cross(std::abs(d.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0}, d));
    const Vec3 e2 = cross(d, e1);
    const double r = 0.5 * (n.radius + p.radius);
    const int count = std::max(2, int(2 * M_PI * r * len * density));
    for (int k = 0; k < count; ++k) {
      const double t = rng.uniform01(), a = rng.uniform(0, 2 * M_PI);
      const Vec3 radial = e1 * std::cos(a) + e2 * std::sin(a);
      const double rr = p.radius + t * (n.radius - p.radius) + rng.normal(0, noise);
      const Vec3 q = p.position + axis * t + radial * rr;
      cloud.positions.push_back(Vec3f(q - cloud.offset));
    }
  }
}

}  // namespace ramus::test
