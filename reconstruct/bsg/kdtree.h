// A nanoflann k-d tree over a vector of Eigen points (or a subset of them, by index).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <nanoflann.hpp>
#include <vector>

namespace ramus::bsg {

class PointIndex {
 public:
  // Indexes pts[ids[i]] (all of pts when ids is empty). The coordinates are copied, in index
  // order and contiguous (3 doubles a point): the tree's build and searches read them at every
  // step, and reading them through ids and Eigen vectors was a good part of the searches' time.
  explicit PointIndex(const std::vector<Eigen::Vector3d>& pts, std::vector<std::uint32_t> ids = {});

  std::size_t size() const { return size_; }
  // Up to k nearest (original indices into pts) with squared distances, nearest first.
  std::size_t knn(const Eigen::Vector3d& q, std::size_t k, std::uint32_t* out, double* d2) const;
  // The nearest point's index, or kNone when the index is empty.
  std::uint32_t nearest(const Eigen::Vector3d& q, double* d2 = nullptr) const;
  // Up to k nearest within `radius` of q, nearest first. The bound prunes the search, which
  // keeps queries in empty space (the axis of a thick branch) cheap.
  std::size_t knn_within(const Eigen::Vector3d& q, std::size_t k, double radius, std::uint32_t* out,
                         double* d2) const;

  // How many points lie within `radius` of q, counted up to `cap`: the search stops at the cap,
  // which on a surface is after the first cell or two.
  std::size_t count_within(const Eigen::Vector3d& q, double radius, std::size_t cap) const;
  // Every point within `radius` of q (original indices, unordered), appended to `out`.
  void within(const Eigen::Vector3d& q, double radius, std::vector<std::uint32_t>& out) const;
  // The points of within(q, radius) that may lie in the slab |(p - q) . d| <= half (d a unit
  // vector), in the order within() gives them: the same traversal, but cells that miss the slab
  // are skipped. Points near the slab's faces may be included (the bounds are widened by a
  // relative 1e-9); the caller applies its exact test. A cross-section's slab is a tenth of its
  // ball, so this reads a fraction of the cells.
  void within_slab(const Eigen::Vector3d& q, double radius, const Eigen::Vector3d& d, double half,
                   std::vector<std::uint32_t>& out) const;

  // nanoflann's search with the caller's result set (nanoflann's interface: size(), full(),
  // worstDist() - the squared radius beyond which cells are skipped, read again after every
  // point - and addPoint(squared distance, index), which receives original indices).
  template <class Result>
  void search(const Eigen::Vector3d& q, Result& result) const {
    if (size() == 0) return;
    Mapped<Result> mapped{result, *this};
    tree_->findNeighbors(mapped, q.data(), nanoflann::SearchParams());
  }

  // nanoflann's dataset interface.
  std::size_t kdtree_get_point_count() const { return size(); }
  double kdtree_get_pt(std::size_t i, std::size_t dim) const { return coords_[3 * i + dim]; }
  template <class B>
  bool kdtree_get_bbox(B&) const {
    return false;
  }

 private:
  std::uint32_t original(std::size_t i) const { return ids_.empty() ? std::uint32_t(i) : ids_[i]; }

  template <class Result>
  struct Mapped {
    using DistanceType = double;
    using IndexType = std::uint32_t;
    Result& result;
    const PointIndex& index;
    std::size_t size() const { return result.size(); }
    bool full() const { return result.full(); }
    double worstDist() const { return result.worstDist(); }
    bool addPoint(double d2, std::uint32_t i) { return result.addPoint(d2, index.original(i)); }
  };

  using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointIndex>,
                                                   PointIndex, 3, std::uint32_t>;
  std::size_t size_;
  std::vector<double> coords_;  // x, y, z of indexed point i at 3i
  std::vector<std::uint32_t> ids_;
  std::unique_ptr<Tree> tree_;
};

// The squared distance from q, a point of `index`, to its nearest other indexed point: the next
// nearest after q itself (or a duplicate of it). With `skip_duplicates` the nearest at a positive
// distance among the next three (duplicates of merged scans are not the scan's spacing). -1 when
// there is none.
double nearest_other_d2(const PointIndex& index, const Eigen::Vector3d& q, bool skip_duplicates);

// Median distance from a point to its nearest other point, over a strided sample of at most
// about 4000 of pts[ids[i]] (0 when fewer than two points). Duplicated points count with
// distance 0 unless `skip_duplicates`, which takes the nearest point at a positive distance.
double median_spacing(const std::vector<Eigen::Vector3d>& pts,
                      const std::vector<std::uint32_t>& ids, bool skip_duplicates);

}  // namespace ramus::bsg
