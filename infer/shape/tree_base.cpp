#include "infer/shape/tree_base.h"

#include <algorithm>

#include "infer/shape/shape_error.h"

namespace ramus::shape {

TreeBase find_base(const std::vector<Vec3>& points) {
  if (points.empty()) throw ShapeError("no points to find a tree's base from");
  double lo = points[0].z, hi = points[0].z;
  for (const Vec3& p : points) {
    lo = std::min(lo, p.z);
    hi = std::max(hi, p.z);
  }
  TreeBase b;
  b.height = hi - lo;
  const double cut = lo + kBaseShare * b.height;
  Vec3 sum;
  double n = 0;
  for (const Vec3& p : points) {
    if (p.z <= cut) {
      sum += p;
      n += 1;
    }
  }
  b.low_centroid = sum / n;  // n >= 1: the lowest point is always in
  b.axis = {b.low_centroid.x, b.low_centroid.y, lo};
  return b;
}

std::vector<Vec3> cloud_points(const PointCloud& cloud) {
  std::vector<Vec3> out;
  out.reserve(cloud.size());
  for (const Vec3f& p : cloud.positions) {
    if (is_finite(p)) out.push_back(Vec3(p));  // readers keep no NaN, but a caller's cloud may
  }
  return out;
}

}  // namespace ramus::shape
