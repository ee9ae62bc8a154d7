// Refusing clouds that hold no tree (tree_presence.h).
#include "infer/wavelet/tree_presence.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace ramus::wavelet {
namespace {

std::string metres(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.3g m", v);
  return buf;
}

}  // namespace

void require_tree(const AlignedCloud& cloud) {
  const std::size_t n = cloud.points.size();
  if (n == 0) throw std::invalid_argument("the scan has no points");
  if (n < kMinTreePoints) {
    throw std::invalid_argument("the scan has " + std::to_string(n) + " point(s); a tree needs at " +
                                "least " + std::to_string(kMinTreePoints) +
                                " to show a trunk and branches");
  }
  Vec3 lo = cloud.points[0], hi = cloud.points[0];
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Vec3& p : cloud.points) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
    mean += Eigen::Vector3d(p.x, p.y, p.z);
  }
  const double height = hi.z - lo.z;
  const double across = std::max(hi.x - lo.x, hi.y - lo.y);
  if (!(height > kMinHeightShare * across) || !(height > 0)) {
    throw std::invalid_argument(
        "no height: all points lie within " + metres(height) + " of one height over " +
        metres(across) + " across, so nothing rises above the base (no trunk, no crown)");
  }
  mean /= double(n);
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vec3& p : cloud.points) {
    const Eigen::Vector3d d = Eigen::Vector3d(p.x, p.y, p.z) - mean;
    cov += d * d.transpose();
  }
  cov /= double(n);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  const Eigen::Vector3d s = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();  // ascending
  if (!(s[0] > kMinThickness * s[2])) {
    throw std::invalid_argument("the points lie on one plane (" + metres(s[0]) +
                                " thick over " + metres(s[2]) +
                                "): no tree, whose trunk and branches need three dimensions");
  }
}

}  // namespace ramus::wavelet
