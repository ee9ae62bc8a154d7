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
    throw std::invalid_argument("the scan has " + std::to_string(n) +
                                " point(s); a tree needs at " + "least " +
                                std::to_string(kMinTreePoints) + " to show a trunk and branches");
  }
  // One pass: bounds, and the moments of the covariance about the first point (shifted data
  // keep the sums well conditioned far from the origin).
  Vec3 lo = cloud.points[0], hi = cloud.points[0];
  const Vec3 o = cloud.points[0];
  double s[3] = {0, 0, 0}, ss[6] = {0, 0, 0, 0, 0, 0};
  for (const Vec3& p : cloud.points) {
    lo = Vec3(std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z));
    hi = Vec3(std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z));
    const double x = p.x - o.x, y = p.y - o.y, z = p.z - o.z;
    s[0] += x;
    s[1] += y;
    s[2] += z;
    ss[0] += x * x;
    ss[1] += x * y;
    ss[2] += x * z;
    ss[3] += y * y;
    ss[4] += y * z;
    ss[5] += z * z;
  }
  const double height = hi.z - lo.z;
  const double across = std::max(hi.x - lo.x, hi.y - lo.y);
  if (!(height > kMinHeightShare * across) || !(height > 0)) {
    throw std::invalid_argument("no height: all points lie within " + metres(height) +
                                " of one height over " + metres(across) +
                                " across, so nothing rises above the base (no trunk, no crown)");
  }
  const double m = double(n);
  Eigen::Matrix3d cov;
  cov(0, 0) = ss[0] / m - s[0] * s[0] / (m * m);
  cov(0, 1) = cov(1, 0) = ss[1] / m - s[0] * s[1] / (m * m);
  cov(0, 2) = cov(2, 0) = ss[2] / m - s[0] * s[2] / (m * m);
  cov(1, 1) = ss[3] / m - s[1] * s[1] / (m * m);
  cov(1, 2) = cov(2, 1) = ss[4] / m - s[1] * s[2] / (m * m);
  cov(2, 2) = ss[5] / m - s[2] * s[2] / (m * m);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  const Eigen::Vector3d sd = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();  // ascending
  if (!(sd[0] > kMinThickness * sd[2])) {
    throw std::invalid_argument("the points lie on one plane (" + metres(sd[0]) + " thick over " +
                                metres(sd[2]) +
                                "): no tree, whose trunk and branches need three dimensions");
  }
}

}  // namespace ramus::wavelet
