#include "reconstruct/forest/detection_score.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <unordered_map>

namespace ramus::forest {

namespace {

Vec3 base_of(const Skeleton& t) {
  const std::vector<std::uint32_t> r = t.roots();
  return r.empty() ? Vec3{NAN, NAN, NAN} : t.nodes[r.front()].position;
}

// The nodes of a set of trees on a grid of cells `near` wide, for "which tree passes near here".
class NodeIndex {
 public:
  NodeIndex(const std::vector<Skeleton>& trees, double near) : near_(near) {
    for (std::size_t t = 0; t < trees.size(); ++t) {
      for (const SkeletonNode& n : trees[t].nodes)
        cells_[key(n.position, 0, 0, 0)].push_back({n.position, t});
    }
  }
  // The tree of the nearest node within `near` of p; -1 when none.
  long nearest_tree(const Vec3& p) const {
    double best = near_ * near_;
    long tree = -1;
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          auto it = cells_.find(key(p, dx, dy, dz));
          if (it == cells_.end()) continue;
          for (const auto& [q, t] : it->second) {
            const Vec3 d = q - p;
            const double d2 = d.x * d.x + d.y * d.y + d.z * d.z;
            if (d2 <= best) best = d2, tree = long(t);
          }
        }
    return tree;
  }

 private:
  std::int64_t key(const Vec3& p, int dx, int dy, int dz) const {
    const auto c = [&](double v, int d) { return std::int64_t(std::floor(v / near_)) + d; };
    return (c(p.x, dx) * 73856093) ^ (c(p.y, dy) * 19349663) ^ (c(p.z, dz) * 83492791);
  }
  double near_;
  std::unordered_map<std::int64_t, std::vector<std::pair<Vec3, std::size_t>>> cells_;
};

// The tree of `other` that most of `tree`'s nodes lie on (-1 when under half lie on any).
long dominant_tree(const Skeleton& tree, const NodeIndex& other, std::size_t other_count) {
  std::vector<std::size_t> votes(other_count, 0);
  for (const SkeletonNode& n : tree.nodes) {
    const long t = other.nearest_tree(n.position);
    if (t >= 0) ++votes[std::size_t(t)];
  }
  if (votes.empty()) return -1;
  const auto best = std::max_element(votes.begin(), votes.end());
  return 2 * *best >= tree.nodes.size() && *best > 0 ? long(best - votes.begin()) : -1;
}

}  // namespace

DetectionScore score_detection(const std::vector<Skeleton>& truth,
                               const std::vector<Skeleton>& detected, double match_distance,
                               double near) {
  DetectionScore s;
  s.truth = truth.size();
  s.detected = detected.size();
  std::vector<std::tuple<double, std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const Vec3 a = base_of(truth[i]);
    for (std::size_t j = 0; j < detected.size(); ++j) {
      const Vec3 b = base_of(detected[j]);
      const double d = std::hypot(a.x - b.x, a.y - b.y);
      if (d <= match_distance) pairs.emplace_back(d, i, j);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<long> truth_match(truth.size(), -1), detected_match(detected.size(), -1);
  double sum = 0;
  for (const auto& [d, i, j] : pairs) {
    if (truth_match[i] >= 0 || detected_match[j] >= 0) continue;
    truth_match[i] = long(j), detected_match[j] = long(i);
    ++s.matched;
    sum += d;
    s.max_base_error = std::max(s.max_base_error, d);
  }
  if (s.matched) s.mean_base_error = sum / double(s.matched);
  const NodeIndex truth_index(truth, near), detected_index(detected, near);
  for (std::size_t i = 0; i < truth.size(); ++i) {
    if (truth_match[i] >= 0) continue;
    const long j = dominant_tree(truth[i], detected_index, detected.size());
    if (j >= 0 && detected_match[std::size_t(j)] >= 0) {
      ++s.merged;
    } else {
      ++s.missed;
    }
  }
  for (std::size_t j = 0; j < detected.size(); ++j) {
    if (detected_match[j] >= 0) continue;
    const long i = dominant_tree(detected[j], truth_index, truth.size());
    if (i >= 0 && truth_match[std::size_t(i)] >= 0) {
      ++s.split;
    } else {
      ++s.false_trees;
    }
  }
  s.precision = s.detected ? double(s.matched) / double(s.detected) : 0;
  s.recall = s.truth ? double(s.matched) / double(s.truth) : 0;
  s.f_score =
      s.precision + s.recall > 0 ? 2 * s.precision * s.recall / (s.precision + s.recall) : 0;
  return s;
}

}  // namespace ramus::forest
