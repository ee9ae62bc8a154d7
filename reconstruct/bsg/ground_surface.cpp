#include "reconstruct/bsg/ground_surface.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/union_find.h"
#include "reconstruct/bsg/kdtree.h"
#include "reconstruct/wood/features.h"

namespace ramus::bsg {

std::vector<std::uint8_t> ground_surface(const std::vector<Eigen::Vector3d>& pts,
                                         const GroundSurfaceParams& p) {
  const std::size_t n = pts.size(), k = std::size_t(std::clamp(p.neighbours, 5, 64));
  std::vector<std::uint8_t> ground(n, 0);
  if (n < k + 1) return ground;
  const PointIndex index(pts);
  std::vector<std::uint32_t> near(n * k);
  std::vector<double> spacing(n);  // distance to the fourth neighbour: the local spacing
  std::vector<std::uint8_t> flat(n, 0);
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
    double d2[64];
    std::uint32_t* ids = &near[i * k];
    const std::size_t m = index.knn(pts[i], k, ids, d2);
    for (std::size_t j = m; j < k; ++j) ids[j] = std::uint32_t(i), d2[j] = 0;
    spacing[i] = std::sqrt(d2[std::min<std::size_t>(4, m - 1)]);
    const wood::Eigenfeatures f = wood::eigenfeatures(pts, ids, m);
    flat[i] = f.scattering < 1 && 1 - f.linearity >= p.min_spread && f.normal_z >= p.min_normal_z;
  });
  // Flat points join their flat neighbours within a few local spacings: the spacing, not a
  // distance, so that the sparse ground far from a station joins as well as the dense ground
  // beside it, and the flat patches at the forks of a spray stay apart.
  UnionFind sets(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!flat[i]) continue;
    for (std::size_t j = 1; j < k; ++j) {
      const std::uint32_t o = near[i * k + j];
      if (!flat[o]) continue;
      const double reach = p.join_spacings * std::max(spacing[i], spacing[o]);
      if ((pts[o] - pts[i]).squaredNorm() <= reach * reach) sets.unite(std::uint32_t(i), o);
    }
  }
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<Eigen::Vector4d> box(n, Eigen::Vector4d(kInf, kInf, -kInf, -kInf));
  for (std::size_t i = 0; i < n; ++i) {
    if (!flat[i]) continue;
    Eigen::Vector4d& b = box[sets.find(std::uint32_t(i))];
    b(0) = std::min(b(0), pts[i].x()), b(1) = std::min(b(1), pts[i].y());
    b(2) = std::max(b(2), pts[i].x()), b(3) = std::max(b(3), pts[i].y());
  }
  std::vector<std::uint8_t> wide(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (!flat[i]) continue;
    const Eigen::Vector4d& b = box[sets.find(std::uint32_t(i))];
    wide[i] = std::max(b(2) - b(0), b(3) - b(1)) >= p.min_extent;
  }
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t votes = 0;
    for (std::size_t j = 0; j < k; ++j) votes += wide[near[i * k + j]];
    ground[i] = wide[i] || 2 * votes > k;
  }
  return ground;
}

}  // namespace ramus::bsg
