// Symmetrization about the scanner plane (see symmetrize.h). Reference: S. Friedman and
// I. Stamos, "Automatic Procedural Modeling of Tree Structures in Point Clouds Using Wavelets",
// 3DV 2013, Section IV-D.
#include "infer/wavelet/symmetrize.h"

#include <Eigen/Core>
#include <algorithm>
#include <vector>

#include "reconstruct/bsg/kdtree.h"

namespace ramus::wavelet {
namespace {

// Relative merge distance when none is given: float positions of a cloud whose extent is D
// carry rounding errors of about 6e-8 D, so 1e-6 D only merges points that are equal as stored.
constexpr double kDefaultMergeShare = 1e-6;

double bbox_diagonal(const PointCloud& cloud) {
  Vec3f lo = cloud.positions.front(), hi = lo;
  for (const Vec3f& p : cloud.positions) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  return length(Vec3(hi) - Vec3(lo));
}

// A direction (normal) mirrored by the same plane: the reflection without the translation.
Vec3 reflect_direction(const Vec3& n, const Vec3& v) { return v - 2.0 * dot(v, n) * n; }

}  // namespace

Vec3 reflect_about_scanner_plane(const Alignment& a, const Vec3& p) {
  // p' = p - 2 ((p - r) . n) n, the reflection in the plane through r with unit normal n.
  return p - 2.0 * dot(p - a.root, a.scanner_dir) * a.scanner_dir;
}

Symmetrized symmetrize(const PointCloud& cloud, const Alignment& a,
                       const SymmetrizeOptions& options) {
  Symmetrized out;
  out.cloud = cloud;
  if (cloud.empty()) return out;
  out.merge_distance = options.merge_distance >= 0 ? options.merge_distance
                                                   : kDefaultMergeShare * bbox_diagonal(cloud);

  // The input points, relative to the offset, in double precision for the k-d tree.
  std::vector<Eigen::Vector3d> input(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Vec3f& p = cloud.positions[i];
    input[i] = Eigen::Vector3d(p.x, p.y, p.z);
  }
  bsg::PointIndex index(input);
  const double merge2 = out.merge_distance * out.merge_distance;
  const bool normals = cloud.normals.size() == cloud.size();
  const bool intensity = cloud.intensity.size() == cloud.size();
  const bool classes = cloud.classification.size() == cloud.size();

  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Vec3 mirrored = reflect_about_scanner_plane(a, cloud.world(i)) - cloud.offset;
    double d2 = 0;
    index.nearest(Eigen::Vector3d(mirrored.x, mirrored.y, mirrored.z), &d2);
    if (d2 <= merge2) {
      ++out.merged;
      continue;
    }
    out.cloud.positions.push_back(Vec3f(mirrored));
    if (normals) {
      out.cloud.normals.push_back(Vec3f(reflect_direction(a.scanner_dir, Vec3(cloud.normals[i]))));
    }
    if (intensity) out.cloud.intensity.push_back(cloud.intensity[i]);
    if (classes) out.cloud.classification.push_back(cloud.classification[i]);
    ++out.reflected;
  }
  return out;
}

}  // namespace ramus::wavelet
