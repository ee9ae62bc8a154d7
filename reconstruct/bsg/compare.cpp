#include "reconstruct/bsg/compare.h"

#include <algorithm>
#include <cmath>

#include "reconstruct/bsg/kdtree.h"

namespace ramus {

namespace {

struct Samples {
  std::vector<Eigen::Vector3d> pos;
  std::vector<double> radius;
  double length = 0;
  std::size_t tips = 0;
};

Samples sample(const std::vector<Skeleton>& skeletons, double spacing) {
  Samples s;
  for (const Skeleton& sk : skeletons) {
    const auto ch = sk.children();
    for (std::uint32_t i = 0; i < sk.size(); ++i) {
      const SkeletonNode& n = sk.nodes[i];
      if (n.parent != kNoParent && ch.count(i) == 0) ++s.tips;
      if (n.parent == kNoParent || n.parent >= sk.size()) continue;
      const SkeletonNode& p = sk.nodes[n.parent];
      const double len = distance(n.position, p.position);
      s.length += len;
      const int steps = std::clamp(int(std::ceil(len / spacing)), 1, 100000);
      for (int k = 0; k <= steps; ++k) {
        const double t = double(k) / steps;
        const Vec3 q = p.position + (n.position - p.position) * t;
        s.pos.emplace_back(q.x, q.y, q.z);
        s.radius.push_back(p.radius + t * (n.radius - p.radius));
      }
    }
  }
  return s;
}

struct Match {
  double within_radius = 0, within_distance = 0, mean_distance = 0;
};

// For each sample of `from`, the nearest sample of `to`; radii come from the truth side.
Match match(const Samples& from, const Samples& to, bool from_is_truth, const CompareOptions& o) {
  Match m;
  if (from.pos.empty() || to.pos.empty()) return m;
  bsg::PointIndex index(to.pos);
  for (std::size_t i = 0; i < from.pos.size(); ++i) {
    double d2;
    const std::uint32_t j = index.nearest(from.pos[i], &d2);
    const double d = std::sqrt(d2);
    const double r = std::max(from_is_truth ? from.radius[i] : to.radius[j], o.min_radius);
    m.within_radius += d <= o.radius_factor * r;
    m.within_distance += d <= o.distance;
    m.mean_distance += d;
  }
  const double n = double(from.pos.size());
  m.within_radius /= n, m.within_distance /= n, m.mean_distance /= n;
  return m;
}

}  // namespace

SkeletonComparison compare_skeletons(const std::vector<Skeleton>& truth,
                                     const std::vector<Skeleton>& reconstructed,
                                     const CompareOptions& o) {
  SkeletonComparison c;
  const Samples t = sample(truth, o.spacing), r = sample(reconstructed, o.spacing);
  const Match precision = match(r, t, false, o), recall = match(t, r, true, o);
  c.precision = precision.within_radius;
  c.precision_distance = precision.within_distance;
  c.recall = recall.within_radius;
  c.recall_distance = recall.within_distance;
  c.chamfer = 0.5 * (precision.mean_distance + recall.mean_distance);
  c.length_truth = t.length;
  c.length_reconstructed = r.length;
  c.length_ratio = t.length > 0 ? r.length / t.length : 0;
  c.branches_truth = t.tips;
  c.branches_reconstructed = r.tips;
  return c;
}

}  // namespace ramus
