#include "reconstruct/bsg/finite_points.h"

#include <algorithm>
#include <string>

namespace ramus::bsg {

bool FinitePoints::coincide() const {
  return !((hi - lo).maxCoeff() > 1e-6 * std::max(1.0, hi.cwiseAbs().maxCoeff()));
}

namespace {

// Gross outliers (a stray return kilometres away, a GPS glitch): points farther outside the box
// of the 1st-99th percentiles than kOutlierExtents x its largest side, on any axis. They would
// set the height, and every scale derived from it, to kilometres. The margin is wide: a tree top
// above a dense ground stays in (its percentile box spans at least the ground and the trunk).
constexpr double kOutlierExtents = 3.0;

void drop_far_outliers(FinitePoints& f, ReconstructResult& res) {
  if (f.count < 100) return;
  Eigen::Vector3d q_lo, q_hi;
  std::vector<double> v;
  v.reserve(f.count);
  for (int a = 0; a < 3; ++a) {
    v.clear();
    for (std::size_t i = 0; i < f.pts.size(); ++i) {
      if (f.keep[i]) v.push_back(f.pts[i][a]);
    }
    const auto lo = v.begin() + std::ptrdiff_t(v.size() / 100);
    const auto hi = v.begin() + std::ptrdiff_t(v.size() - 1 - v.size() / 100);
    std::nth_element(v.begin(), lo, v.end());
    q_lo[a] = *lo;
    std::nth_element(v.begin(), hi, v.end());
    q_hi[a] = *hi;
  }
  const double margin = kOutlierExtents * std::max((q_hi - q_lo).maxCoeff(), 1e-9);
  const Eigen::Vector3d lo = q_lo.array() - margin, hi = q_hi.array() + margin;
  std::size_t dropped = 0;
  f.lo = Eigen::Vector3d::Constant(1e300);
  f.hi = -f.lo;
  for (std::size_t i = 0; i < f.pts.size(); ++i) {
    if (!f.keep[i]) continue;
    if ((f.pts[i].array() < lo.array()).any() || (f.pts[i].array() > hi.array()).any()) {
      f.keep[i] = 0;
      ++dropped;
      continue;
    }
    f.lo = f.lo.cwiseMin(f.pts[i]);
    f.hi = f.hi.cwiseMax(f.pts[i]);
  }
  if (dropped == 0) return;
  f.count -= dropped;
  res.counts.outlier_points = dropped;
  res.notes.push_back(std::to_string(dropped) + (dropped == 1 ? " point" : " points") +
                      " far outside the rest of the cloud (more than 3 x its extent) ignored as "
                      "outliers");
}

}  // namespace

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
  drop_far_outliers(f, res);
  if (finite < 2) {
    throw ReconstructError("the point cloud has " + std::to_string(finite) +
                           " point(s) with finite coordinates; a tree needs many more");
  }
  return f;
}

}  // namespace ramus::bsg
