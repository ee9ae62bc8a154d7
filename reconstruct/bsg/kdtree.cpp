#include "reconstruct/bsg/kdtree.h"

#include <cmath>

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

namespace {

// nanoflann's radius result set, appending the indices straight to the caller's vector (the
// library's collects (index, distance) pairs, which within() would copy once more).
class AppendWithin {
 public:
  using DistanceType = double;
  using IndexType = std::uint32_t;
  AppendWithin(double radius2, std::vector<std::uint32_t>& out)
      : out_(out), radius2_(radius2), start_(out.size()) {}
  std::size_t size() const { return out_.size() - start_; }
  bool full() const { return true; }
  double worstDist() const { return radius2_; }
  bool addPoint(double dist, std::uint32_t index) {
    if (dist < radius2_) out_.push_back(index);
    return true;
  }

 private:
  std::vector<std::uint32_t>& out_;
  double radius2_;
  std::size_t start_;
};

// nanoflann's result set counting the points within a radius, up to a cap: addPoint's false
// ends the search.
class CountWithin {
 public:
  using DistanceType = double;
  using IndexType = std::uint32_t;
  CountWithin(double radius2, std::size_t cap) : radius2_(radius2), cap_(cap) {}
  std::size_t size() const { return count_; }
  bool full() const { return true; }
  double worstDist() const { return radius2_; }
  bool addPoint(double dist, std::uint32_t) {
    if (dist < radius2_) ++count_;
    return count_ < cap_;
  }

 private:
  double radius2_;
  std::size_t cap_, count_ = 0;
};

}  // namespace

std::size_t PointIndex::count_within(const Eigen::Vector3d& q, double radius,
                                     std::size_t cap) const {
  if (size() == 0 || cap == 0 || !(radius > 0)) return 0;
  CountWithin result(radius * radius, cap);
  tree_->findNeighbors(result, q.data(), nanoflann::SearchParams(32, 0, false));
  return result.size();
}

void PointIndex::within(const Eigen::Vector3d& q, double radius,
                        std::vector<std::uint32_t>& out) const {
  if (size() == 0 || !(radius > 0)) return;
  const std::size_t start = out.size();
  AppendWithin result(radius * radius, out);
  tree_->findNeighbors(result, q.data(), nanoflann::SearchParams(32, 0, false));
  if (!ids_.empty()) {
    for (std::size_t i = start; i < out.size(); ++i) out[i] = ids_[out[i]];
  }
}

void PointIndex::within_slab(const Eigen::Vector3d& q, double radius, const Eigen::Vector3d& d,
                             double half, std::vector<std::uint32_t>& out) const {
  if (size() == 0 || !(radius > 0)) return;
  using Node = Tree::Node;
  const double r2 = radius * radius;
  const double r2_wide = r2 * (1 + 1e-9);
  const double ad[3] = {std::abs(d.x()), std::abs(d.y()), std::abs(d.z())};
  // Whether the cell [lo, hi] may hold a point of the ball and the slab (both widened).
  auto may_hold = [&](const double* lo, const double* hi) {
    double box2 = 0, s = 0, ext = 0;
    for (int k = 0; k < 3; ++k) {
      const double below = lo[k] - q[k], above = q[k] - hi[k];
      const double gap = below > 0 ? below : (above > 0 ? above : 0.0);
      box2 += gap * gap;
      s += (0.5 * (lo[k] + hi[k]) - q[k]) * d[k];
      ext += 0.5 * (hi[k] - lo[k]) * ad[k];
    }
    return box2 <= r2_wide && std::abs(s) - ext <= half + 1e-9 * (std::abs(s) + ext + half);
  };
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) lo[k] = tree_->root_bbox[k].low, hi[k] = tree_->root_bbox[k].high;
  // nanoflann's order (Tree::searchLevel): at each split the child on the query's side first.
  auto visit = [&](auto&& self, const Node* node) -> void {
    if (!may_hold(lo, hi)) return;
    if (node->child1 == nullptr && node->child2 == nullptr) {
      for (auto i = node->node_type.lr.left; i < node->node_type.lr.right; ++i) {
        const std::uint32_t a = tree_->vAcc[i];
        const double* p = &coords_[3 * std::size_t(a)];
        // nanoflann's L2_Simple_Adaptor::evalMetric, term by term.
        double dist = 0;
        for (int k = 0; k < 3; ++k) {
          const double diff = q[k] - p[k];
          dist += diff * diff;
        }
        if (!(dist < r2)) continue;
        const double t = (p[0] - q[0]) * d[0] + (p[1] - q[1]) * d[1] + (p[2] - q[2]) * d[2];
        if (std::abs(t) > half + 1e-9 * (std::abs(t) + half + radius)) continue;
        out.push_back(original(a));
      }
      return;
    }
    const int idx = node->node_type.sub.divfeat;
    const double val = q[idx];
    const double divlow = node->node_type.sub.divlow, divhigh = node->node_type.sub.divhigh;
    // child1 holds the points up to divlow, child2 those from divhigh.
    auto child1 = [&] {
      const double keep = hi[idx];
      hi[idx] = divlow;
      self(self, node->child1);
      hi[idx] = keep;
    };
    auto child2 = [&] {
      const double keep = lo[idx];
      lo[idx] = divhigh;
      self(self, node->child2);
      lo[idx] = keep;
    };
    if ((val - divlow) + (val - divhigh) < 0) {
      child1(), child2();
    } else {
      child2(), child1();
    }
  };
  visit(visit, tree_->root_node);
}

double nearest_other_d2(const PointIndex& index, const Eigen::Vector3d& q, bool skip_duplicates) {
  std::uint32_t nn[4];
  double d2[4];
  const std::size_t n = index.knn(q, skip_duplicates ? 4 : 2, nn, d2);
  // nn[0] is the point itself (or a duplicate of it).
  for (std::size_t j = 1; j < n; ++j) {
    if (!skip_duplicates || d2[j] > 0) return d2[j];
  }
  return -1.0;
}

double median_spacing(const std::vector<Eigen::Vector3d>& pts,
                      const std::vector<std::uint32_t>& ids, bool skip_duplicates) {
  if (ids.size() < 2) return 0.0;
  const PointIndex index(pts, ids);
  std::vector<double> d;
  const std::size_t stride = std::max<std::size_t>(1, ids.size() / 4000);
  for (std::size_t i = 0; i < ids.size(); i += stride) {
    const double d2 = nearest_other_d2(index, pts[ids[i]], skip_duplicates);
    if (d2 >= 0) d.push_back(std::sqrt(d2));
  }
  if (d.empty()) return 0.0;
  std::nth_element(d.begin(), d.begin() + std::ptrdiff_t(d.size() / 2), d.end());
  return d[d.size() / 2];
}

}  // namespace ramus::bsg
