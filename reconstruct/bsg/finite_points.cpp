#include "reconstruct/bsg/finite_points.h"

#include <algorithm>
#include <string>

namespace ramus::bsg {

bool FinitePoints::coincide() const {
  return !((hi - lo).maxCoeff() > 1e-6 * std::max(1.0, hi.cwiseAbs().maxCoeff()));
}

FinitePoints read_finite_points(const PointCloud& cloud, ReconstructResult& res) {
  res.counts.input_points = cloud.size();
  res.point_tree.assign(cloud.size(), ReconstructResult::kNoTree);
  if (cloud.empty()) throw ReconstructError("the point cloud is empty");
  FinitePoints f;
  f.pts.resize(cloud.size());
  f.keep.assign(cloud.size(), 0);
  f.lo = Eigen::Vector3d::Constant(1e300);
  f.hi = -f.lo;
  std::size_t& finite = f.count;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Vec3f& p = cloud.positions[i];
    f.pts[i] = Eigen::Vector3d(p.x, p.y, p.z);
    if (!is_finite(p)) continue;
    f.keep[i] = 1;
    ++finite;
    f.lo = f.lo.cwiseMin(f.pts[i]);
    f.hi = f.hi.cwiseMax(f.pts[i]);
  }
  res.counts.dropped_points = cloud.size() - finite;
  if (res.counts.dropped_points) {
    res.notes.push_back(std::to_string(res.counts.dropped_points) +
                        " points with non-finite coordinates were ignored");
  }
  if (finite < 2) {
    throw ReconstructError("the point cloud has " + std::to_string(finite) +
                           " point(s) with finite coordinates; a tree needs many more");
  }
  return f;
}

}  // namespace ramus::bsg
