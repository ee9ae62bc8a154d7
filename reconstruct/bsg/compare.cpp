#include "reconstruct/bsg/compare.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>

#include "reconstruct/bsg/bsg.h"
#include "reconstruct/bsg/centre_line.h"
#include "reconstruct/bsg/circle_fit.h"
#include "reconstruct/bsg/kdtree.h"

namespace ramus {

namespace {

struct Samples {
  std::vector<Eigen::Vector3d> pos;
  std::vector<Eigen::Vector3d> dir;  // unit direction of the sample's segment
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
      const Vec3 d = len > 0 ? (n.position - p.position) * (1 / len) : Vec3{0, 0, 1};
      for (int k = 0; k <= steps; ++k) {
        const double t = double(k) / steps;
        const Vec3 q = p.position + (n.position - p.position) * t;
        s.pos.emplace_back(q.x, q.y, q.z);
        s.dir.emplace_back(d.x, d.y, d.z);
        s.radius.push_back(p.radius + t * (n.radius - p.radius));
      }
    }
  }
  return s;
}

struct Match {
  double within_radius = 0, within_radius_1 = 0, mean_distance = 0;
  std::vector<double> within;  // per distance of `distances`
};

// For each sample of `from`, the nearest sample of `to`; radii come from the truth side. `hit`,
// when given, gets per sample of `from` whether it is within radius_factor x the radius.
// `distances`: the fixed distances scored, each a share of the samples of `from`.
Match match(const Samples& from, const Samples& to, bool from_is_truth, const CompareOptions& o,
            const std::vector<double>& distances, std::vector<std::uint8_t>* hit = nullptr) {
  Match m;
  m.within.assign(distances.size(), 0.0);
  if (hit) hit->assign(from.pos.size(), 0);
  if (from.pos.empty() || to.pos.empty()) return m;
  bsg::PointIndex index(to.pos);
  for (std::size_t i = 0; i < from.pos.size(); ++i) {
    double d2;
    const std::uint32_t j = index.nearest(from.pos[i], &d2);
    const double d = std::sqrt(d2);
    const double r = std::max(from_is_truth ? from.radius[i] : to.radius[j], o.min_radius);
    m.within_radius += d <= o.radius_factor * r;
    if (hit) (*hit)[i] = d <= o.radius_factor * r;
    m.within_radius_1 += d <= r;
    for (std::size_t k = 0; k < distances.size(); ++k) m.within[k] += d <= distances[k];
    m.mean_distance += d;
  }
  const double n = double(from.pos.size());
  m.within_radius /= n, m.within_radius_1 /= n, m.mean_distance /= n;
  for (double& w : m.within) w /= n;
  return m;
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  const auto k = std::ptrdiff_t(std::min(v.size() - 1, std::size_t(q * double(v.size()))));
  std::nth_element(v.begin(), v.begin() + k, v.end());
  return v[std::size_t(k)];
}

// Per truth sample: whether the scan's points on its bark cover CompareOptions::seen_arc of its
// circumference (compare.h). Truth radii unfloored: the bark is where the mesh put it.
std::vector<std::uint8_t> seen_samples(const Samples& t, const CompareOptions& o) {
  std::vector<std::uint8_t> seen(t.pos.size(), 0);
  if (!o.scan || o.scan->empty()) return seen;
  std::vector<Eigen::Vector3d> pts;
  pts.reserve(o.scan->size());
  for (std::size_t i = 0; i < o.scan->size(); ++i) {
    const Vec3 w = o.scan->world(i);
    pts.emplace_back(w.x, w.y, w.z);
  }
  const bsg::PointIndex index(pts);
  std::vector<std::uint32_t> near;
  std::vector<Eigen::Vector2d> uv;
  std::vector<double> w, angles;
  for (std::size_t i = 0; i < t.pos.size(); ++i) {
    const double r = t.radius[i], band = o.bark_band * r + o.bark_floor;
    const double half = std::max(0.25 * r, o.spacing);
    Eigen::Vector3d e1, e2;
    bsg::perpendicular_frame(t.dir[i], e1, e2);
    // The cross-section's disc out to the band's outer edge, then the band itself.
    bsg::gather_slab(t.pos[i], t.dir[i], e1, e2, r + band, half, index, pts, {}, near, uv, w);
    angles.clear();
    for (const Eigen::Vector2d& p : uv) {
      if (std::abs(p.norm() - r) <= band) angles.push_back(std::atan2(p.y(), p.x()));
    }
    seen[i] = angles.size() >= 3 && bsg::angular_coverage(angles) >= o.seen_arc;
  }
  return seen;
}

// Centre-line error per radius class: exact distances to the segments of the nearest samples
// (the sampling step would otherwise add up to half a step to every distance).
void centre_errors(const std::vector<Skeleton>& rec, const Samples& t,
                   const std::vector<std::uint8_t>& seen, const CompareOptions& o,
                   SkeletonComparison& c) {
  if (o.radius_classes.size() < 2) return;
  std::vector<Eigen::Vector3d> along, seg_a, seg_b;
  std::vector<std::uint32_t> seg_of;
  for (const Skeleton& sk : rec) {
    for (const SkeletonNode& n : sk.nodes) {
      if (n.parent == kNoParent || n.parent >= sk.size()) continue;
      const Vec3& p = sk.nodes[n.parent].position;
      const Eigen::Vector3d a(p.x, p.y, p.z), b(n.position.x, n.position.y, n.position.z);
      const int steps = std::clamp(int(std::ceil((b - a).norm() / o.spacing)), 1, 100000);
      for (int k = 0; k <= steps; ++k) {
        along.push_back(a + (b - a) * (double(k) / steps));
        seg_of.push_back(std::uint32_t(seg_a.size()));
      }
      seg_a.push_back(a), seg_b.push_back(b);
    }
  }
  const std::size_t classes = o.radius_classes.size() - 1;
  std::vector<std::vector<double>> rel(classes), rel_seen(classes);
  std::vector<double> all, all_seen;
  std::unique_ptr<bsg::PointIndex> index;
  if (!along.empty()) index = std::make_unique<bsg::PointIndex>(along);
  for (std::size_t i = 0; i < t.pos.size(); ++i) {
    const double r = t.radius[i];
    const auto it = std::upper_bound(o.radius_classes.begin(), o.radius_classes.end(), r);
    if (it == o.radius_classes.begin() || it == o.radius_classes.end()) continue;
    const std::size_t k = std::size_t(it - o.radius_classes.begin()) - 1;
    double best = std::numeric_limits<double>::infinity();
    if (index) {
      std::uint32_t ids[8];
      double d2[8];
      const std::size_t m = index->knn(t.pos[i], 8, ids, d2);
      for (std::size_t j = 0; j < m; ++j) {
        const std::uint32_t s = seg_of[ids[j]];
        best = std::min(best, bsg::point_segment_distance(t.pos[i], seg_a[s], seg_b[s]));
      }
    }
    rel[k].push_back(best / r);
    all.push_back(best / r);
    if (seen[i]) rel_seen[k].push_back(best / r), all_seen.push_back(best / r);
    if (o.keep_samples) {
      const Eigen::Vector3d& q = t.pos[i];
      const Eigen::Vector3d& d = t.dir[i];
      c.centre_samples.push_back(
          {Vec3{q.x(), q.y(), q.z()}, Vec3{d.x(), d.y(), d.z()}, r, best / r, seen[i] != 0});
    }
  }
  for (std::size_t k = 0; k < classes; ++k) {
    CentreError e;
    std::vector<double> found;
    for (double x : rel[k]) {
      if (x <= 2) found.push_back(x);
    }
    e.median_found = quantile(found, 0.5);
    e.lo = o.radius_classes[k], e.hi = o.radius_classes[k + 1];
    e.samples = rel[k].size();
    e.median = quantile(rel[k], 0.5);
    e.p90 = quantile(rel[k], 0.9);
    e.seen = rel_seen[k].size();
    e.median_seen = quantile(rel_seen[k], 0.5);
    c.centre_error.push_back(e);
  }
  c.centre_error_median = quantile(all, 0.5);
  c.centre_error_median_seen = quantile(all_seen, 0.5);
}

}  // namespace

SkeletonComparison compare_skeletons(const std::vector<Skeleton>& truth,
                                     const std::vector<Skeleton>& reconstructed,
                                     const CompareOptions& o) {
  SkeletonComparison c;
  const Samples t = sample(truth, o.spacing), r = sample(reconstructed, o.spacing);
  std::vector<std::uint8_t> hit;
  // The fixed distance is scored as the last of the further ones: one count per distance.
  std::vector<double> distances = o.distances;
  distances.push_back(o.distance);
  Match precision = match(r, t, false, o, distances),
        recall = match(t, r, true, o, distances, &hit);
  const std::vector<std::uint8_t> seen = seen_samples(t, o);
  std::size_t seen_count = 0, seen_hit = 0;
  for (std::size_t i = 0; i < seen.size(); ++i)
    seen_count += seen[i], seen_hit += seen[i] && hit[i];
  if (!t.pos.empty()) c.seen_fraction = double(seen_count) / double(t.pos.size());
  if (seen_count > 0) c.recall_seen = double(seen_hit) / double(seen_count);
  c.precision = precision.within_radius;
  c.recall = recall.within_radius;
  c.precision_1r = precision.within_radius_1;
  c.recall_1r = recall.within_radius_1;
  c.precision_distance = precision.within.back();
  c.recall_distance = recall.within.back();
  precision.within.pop_back(), recall.within.pop_back();
  c.precision_within = std::move(precision.within);
  c.recall_within = std::move(recall.within);
  c.chamfer = 0.5 * (precision.mean_distance + recall.mean_distance);
  c.length_truth = t.length;
  c.length_reconstructed = r.length;
  c.length_ratio = t.length > 0 ? r.length / t.length : 0;
  c.branches_truth = t.tips;
  c.branches_reconstructed = r.tips;
  centre_errors(reconstructed, t, seen, o, c);
  return c;
}

}  // namespace ramus
