#include "reconstruct/bsg/sample_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "reconstruct/bsg/kdtree.h"

namespace ramus::bsg {

namespace {

// nanoflann result set for the nearest edge of a sample q among the edges with points along
// them in the index. Every point of an edge lies within `reach` of one of the edge's along
// points, so an edge nearer than the best so far has an along point within best + reach: the
// search radius shrinks with the best edge, and the result is the nearest edge exactly.
class NearestEdge {
 public:
  using DistanceType = double;
  using IndexType = std::uint32_t;
  NearestEdge(const Eigen::Vector3d& q, double reach, double best, std::uint32_t nearest,
              const std::vector<std::uint32_t>& along_of,
              const std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>>& ends,
              std::vector<std::uint32_t>& stamp, std::uint32_t query)
      : q_(q),
        reach_(reach),
        best_(best),
        nearest_(nearest),
        query_(query),
        along_of_(along_of),
        ends_(ends),
        stamp_(stamp) {}
  std::size_t size() const { return 1; }
  bool full() const { return true; }
  double worstDist() const {
    if (!std::isfinite(best_)) return std::numeric_limits<double>::infinity();
    // Widened by a relative 1e-9, so that no along point within best + reach is skipped through
    // rounding.
    const double r = (best_ + reach_) * (1 + 1e-9);
    return r * r;
  }
  bool addPoint(double d2, std::uint32_t i) {
    // nanoflann reads the radius once a leaf: the points of a leaf after a nearer edge are
    // tested against the new one here.
    if (!(d2 < worstDist())) return true;
    const std::uint32_t e = along_of_[i];
    if (stamp_[e] == query_) return true;  // each edge once
    stamp_[e] = query_;
    const double d = point_segment_distance(q_, ends_[e].first, ends_[e].second);
    // The lower slot on a tie: the edge does not depend on the order of the search.
    if (d < best_ || (d == best_ && e < nearest_)) best_ = d, nearest_ = e;
    return true;
  }
  double best() const { return best_; }
  std::uint32_t nearest() const { return nearest_; }

 private:
  Eigen::Vector3d q_;
  double reach_, best_;
  std::uint32_t nearest_, query_;
  const std::vector<std::uint32_t>& along_of_;
  const std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>>& ends_;
  std::vector<std::uint32_t>& stamp_;
};

}  // namespace

SampleDistances::SampleDistances(const std::vector<Eigen::Vector3d>& samples, double edge_sample)
    : samples_(samples),
      edge_sample_(edge_sample),
      best_(samples.size(), std::numeric_limits<double>::infinity()),
      nearest_(samples.size(), kNone) {}

double SampleDistances::mean(const Bsg& bsg, const std::vector<std::uint32_t>& counts) {
  if (bsg.size() < 2 || samples_.empty()) return 0.0;
  // The slots of this BSG's edges; an edge not met before gets a slot and its along points.
  std::vector<std::uint8_t> current(ends_.size(), 0);
  const std::size_t old_along = along_.size();
  for (std::uint32_t v = 1; v < bsg.size(); ++v) {
    const Eigen::Vector3d& a = bsg.pos[bsg.parent[v]];
    const Eigen::Vector3d& b = bsg.pos[v];
    const Key key{a.x(), a.y(), a.z(), b.x(), b.y(), b.z()};
    const auto [it, added] = slot_.emplace(key, std::uint32_t(ends_.size()));
    if (added) {
      ends_.emplace_back(a, b);
      current.push_back(0);
      const Eigen::Vector3d d = b - a;
      const double per = edge_sample_ > 0 ? d.norm() / edge_sample_ : 1.0;
      const int steps = int(std::clamp(std::ceil(per), 1.0, 1000.0));
      for (int s = 0; s <= steps; ++s) {
        along_.push_back(a + d * (double(s) / steps));
        along_of_.push_back(it->second);
      }
      reach_ = std::max(reach_, 0.5 * d.norm() / steps);
    }
    current[it->second] = 1;
  }
  // Samples whose nearest edge is gone (it is forgotten) are searched among all current edges;
  // the others only among the new ones (an edge that is gone was not nearer than their nearest).
  std::vector<std::uint32_t> lost;
  for (std::uint32_t i = 0; i < samples_.size(); ++i) {
    if (nearest_[i] != kNone && !current[nearest_[i]]) nearest_[i] = kNone;
    if (nearest_[i] == kNone) lost.push_back(i);
  }
  std::vector<std::uint32_t> stamp(ends_.size(), 0);
  std::uint32_t query = 0;
  if (along_.size() > old_along && lost.size() < samples_.size()) {
    std::vector<std::uint32_t> ids(along_.size() - old_along);
    for (std::size_t k = 0; k < ids.size(); ++k) ids[k] = std::uint32_t(old_along + k);
    const PointIndex fresh(along_, std::move(ids));
    for (std::uint32_t i = 0; i < samples_.size(); ++i) {
      if (nearest_[i] == kNone) continue;
      NearestEdge r(samples_[i], reach_, best_[i], nearest_[i], along_of_, ends_, stamp, ++query);
      fresh.search(samples_[i], r);
      best_[i] = r.best(), nearest_[i] = r.nearest();
    }
  }
  if (!lost.empty()) {
    std::vector<std::uint32_t> ids;
    if (old_along > 0) {
      for (std::uint32_t k = 0; k < along_.size(); ++k) {
        if (current[along_of_[k]]) ids.push_back(k);
      }
    }
    const PointIndex all(along_, std::move(ids));  // the first call: every along point
    for (std::uint32_t i : lost) {
      NearestEdge r(samples_[i], reach_, std::numeric_limits<double>::infinity(), kNone, along_of_,
                    ends_, stamp, ++query);
      all.search(samples_[i], r);
      best_[i] = r.best(), nearest_[i] = r.nearest();
    }
  }
  double sum = 0, weight = 0;
  for (std::size_t i = 0; i < samples_.size(); ++i) {
    sum += counts[i] * best_[i];
    weight += counts[i];
  }
  return weight > 0 ? sum / weight : 0.0;
}

}  // namespace ramus::bsg
