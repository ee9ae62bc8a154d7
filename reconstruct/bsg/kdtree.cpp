#include "reconstruct/bsg/kdtree.h"

#include "reconstruct/bsg/bsg.h"

namespace ramus::bsg {

PointIndex::PointIndex(const std::vector<Eigen::Vector3d>& pts, std::vector<std::uint32_t> ids)
    : size_(ids.empty() ? pts.size() : ids.size()), ids_(std::move(ids)) {
  coords_.resize(3 * size_);
  for (std::size_t i = 0; i < size_; ++i) {
    const Eigen::Vector3d& p = ids_.empty() ? pts[i] : pts[ids_[i]];
    coords_[3 * i] = p.x(), coords_[3 * i + 1] = p.y(), coords_[3 * i + 2] = p.z();
  }
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

namespace {

// nanoflann's k-nearest result set with the search radius preset to a bound: the tree then
// never descends into cells farther than the bound.
class BoundedKnn {
 public:
  using DistanceType = double;
  using IndexType = std::uint32_t;
  BoundedKnn(std::size_t capacity, double bound2, std::uint32_t* ids, double* d2)
      : ids_(ids), d2_(d2), capacity_(capacity), bound2_(bound2) {}
  std::size_t size() const { return count_; }
  bool full() const { return count_ == capacity_; }
  double worstDist() const { return count_ == capacity_ ? d2_[capacity_ - 1] : bound2_; }
  bool addPoint(double dist, std::uint32_t index) {
    if (!(dist < worstDist())) return true;
    std::size_t i = count_ < capacity_ ? count_++ : capacity_ - 1;
    for (; i > 0 && d2_[i - 1] > dist; --i) ids_[i] = ids_[i - 1], d2_[i] = d2_[i - 1];
    ids_[i] = index, d2_[i] = dist;
    return true;
  }

 private:
  std::uint32_t* ids_;
  double* d2_;
  std::size_t capacity_, count_ = 0;
  double bound2_;
};

}  // namespace

std::size_t PointIndex::knn_within(const Eigen::Vector3d& q, std::size_t k, double radius,
                                   std::uint32_t* out, double* d2) const {
  if (size() == 0 || k == 0) return 0;
  BoundedKnn result(k, radius * radius, out, d2);
  tree_->findNeighbors(result, q.data(), nanoflann::SearchParams());
  const std::size_t n = result.size();
  for (std::size_t i = 0; i < n; ++i) out[i] = original(out[i]);
  return n;
}

void PointIndex::within(const Eigen::Vector3d& q, double radius,
                        std::vector<std::uint32_t>& out) const {
  if (size() == 0 || !(radius > 0)) return;
  std::vector<std::pair<std::uint32_t, double>> found;
  tree_->radiusSearch(q.data(), radius * radius, found, nanoflann::SearchParams(32, 0, false));
  for (const auto& f : found) out.push_back(original(f.first));
}

double median_spacing(const std::vector<Eigen::Vector3d>& pts,
                      const std::vector<std::uint32_t>& ids, bool skip_duplicates) {
  if (ids.size() < 2) return 0.0;
  const PointIndex index(pts, ids);
  std::vector<double> d;
  const std::size_t stride = std::max<std::size_t>(1, ids.size() / 4000);
  const std::size_t k = skip_duplicates ? 4 : 2;
  for (std::size_t i = 0; i < ids.size(); i += stride) {
    std::uint32_t nn[4];
    double d2[4];
    const std::size_t n = index.knn(pts[ids[i]], k, nn, d2);
    // nn[0] is the point itself (or a duplicate of it).
    for (std::size_t j = 1; j < n; ++j) {
      if (!skip_duplicates || d2[j] > 0) {
        d.push_back(std::sqrt(d2[j]));
        break;
      }
    }
  }
  if (d.empty()) return 0.0;
  std::nth_element(d.begin(), d.begin() + std::ptrdiff_t(d.size() / 2), d.end());
  return d[d.size() / 2];
}

}  // namespace ramus::bsg
