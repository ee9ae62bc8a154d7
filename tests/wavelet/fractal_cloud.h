// A synthetic scan of an exactly self-similar tree for the inference tests: a trunk that forks
// into two branches at every level (shorter by 0.65, turned 35 degrees apart about alternating
// axes), sampled with points around each segment. Same seed, same cloud.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/rng.h"
#include "infer/wavelet/alignment.h"

namespace ramus::wavelet::test {

inline Vec3 rotate(const Vec3& v, const Vec3& axis, double angle) {  // Rodrigues
  const double c = std::cos(angle), s = std::sin(angle);
  return v * c + cross(axis, v) * s + axis * (dot(axis, v) * (1 - c));
}

// Points in the aligned frame (root at the origin, z up), `per_metre` points per metre of branch.
inline AlignedCloud fractal_tree_cloud(std::uint64_t seed, int depth = 6, double per_metre = 400) {
  Rng rng(seed);
  AlignedCloud cloud;
  struct Branch {
    Vec3 base, dir;
    double length, radius;
    int level;
  };
  std::vector<Branch> pending{{Vec3(0, 0, 0), Vec3(0, 0, 1), 1.0, 0.05, 0}};
  while (!pending.empty()) {
    const Branch b = pending.back();
    pending.pop_back();
    const int n = int(b.length * per_metre) + 1;
    for (int i = 0; i < n; ++i) {
      const double t = rng.uniform01() * b.length;
      const Vec3 jitter(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
      cloud.points.push_back(b.base + b.dir * t + jitter * b.radius);
    }
    if (b.level + 1 >= depth) continue;
    const Vec3 tip = b.base + b.dir * b.length;
    const Vec3 axis = b.level % 2 == 0 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    for (double sign : {-1.0, 1.0}) {
      const Vec3 d = normalized(rotate(b.dir, axis, sign * 35.0 * 3.14159265358979 / 180));
      pending.push_back({tip, d, b.length * 0.65, b.radius * 0.7, b.level + 1});
    }
  }
  // The lowest point is the root: shift so that it is at the origin, as align_cloud does.
  double zmin = 0;
  for (const Vec3& p : cloud.points) zmin = std::min(zmin, p.z);
  for (Vec3& p : cloud.points) p.z -= zmin;
  cloud.alignment.source = ScannerSource::given;
  return cloud;
}

}  // namespace ramus::wavelet::test
