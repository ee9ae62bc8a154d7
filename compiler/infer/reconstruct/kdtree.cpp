#include "compiler/infer/reconstruct/kdtree.h"

#include "compiler/infer/reconstruct/bsg.h"

namespace ramus::bsg {

PointIndex::PointIndex(const std::vector<Eigen::Vector3d>& pts, std::vector<std::uint32_t> ids)
    : pts_(pts), ids_(std::move(ids)) {
  tree_ = std::make_unique<Tree>(3, *this, nanoflann::KDTreeSingleIndexAdaptorParams(16));
}

std::size_t PointIndex::knn(const Eigen::Vector3d& q, std::size_t k, std::uint32_t* out,
                            double* d2) const {
  if (size() == 0 || k == 0) return 0;
  std::size_t n = tree_->knnSearch(q.data(), k, out, d2);
  for (std::size_t i = 0; i < n; ++i) out[i] = original(out[i]);
  return n;
}

std::uint32_t PointIndex::nearest(const Eigen::Vector3d& q, double* d2) const {
  std::uint32_t idx;
  double d;
  if (knn(q, 1, &idx, &d) == 0) return kNone;
  if (d2) *d2 = d;
  return idx;
}

}  // namespace ramus::bsg
