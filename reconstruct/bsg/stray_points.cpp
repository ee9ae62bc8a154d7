#include "reconstruct/bsg/stray_points.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "reconstruct/bsg/kdtree.h"

namespace ramus::bsg {

namespace {

std::uint32_t find_root(std::vector<std::uint32_t>& up, std::uint32_t k) {
  while (up[k] != k) k = up[k] = up[up[k]];
  return k;
}

// The kept points' indices, ascending.
std::vector<std::uint32_t> kept_ids(const std::vector<std::uint8_t>& keep) {
  std::vector<std::uint32_t> ids;
  for (std::size_t i = 0; i < keep.size(); ++i) {
    if (keep[i]) ids.push_back(std::uint32_t(i));
  }
  return ids;
}

// Marks the points of `ids` in clusters of fewer than `min_cluster` points linked by steps
// shorter than `radius` (when some cluster is that large). A point with min_cluster within reach
// (itself included; the count stops there) is in a cluster that large; the others have few
// neighbours, and joining them with those gives the small clusters exactly.
void mark_small_clusters(const std::vector<Eigen::Vector3d>& pts,
                         const std::vector<std::uint32_t>& ids, const PointIndex& index,
                         double radius, std::size_t min_cluster, std::vector<std::uint8_t>& stray) {
  std::vector<std::uint32_t> within(ids.size(), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ids.size()),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t k = range.begin(); k != range.end(); ++k) {
                        within[k] =
                            std::uint32_t(index.count_within(pts[ids[k]], radius, min_cluster));
                      }
                    });
  // Union-find over the points below the cap; a root's cluster is large when it has
  // min_cluster points or touches a point with min_cluster within reach.
  std::vector<std::uint32_t> up(ids.size());
  for (std::uint32_t k = 0; k < up.size(); ++k) up[k] = k;
  std::vector<std::uint8_t> large(ids.size(), 0);
  std::vector<std::uint32_t> near;
  bool any_large = false;
  for (std::uint32_t k = 0; k < ids.size(); ++k) {
    if (within[k] >= min_cluster) {
      any_large = true;
      continue;
    }
    near.clear();
    index.within(pts[ids[k]], radius, near);
    for (std::uint32_t id : near) {
      const auto other = std::uint32_t(std::lower_bound(ids.begin(), ids.end(), id) - ids.begin());
      if (within[other] >= min_cluster)
        large[k] = 1;
      else
        up[find_root(up, k)] = find_root(up, other);
    }
  }
  std::vector<std::uint32_t> size(ids.size(), 0);
  for (std::uint32_t k = 0; k < ids.size(); ++k) {
    if (within[k] >= min_cluster) continue;
    const std::uint32_t r = find_root(up, k);
    ++size[r];
    large[r] |= large[k];
  }
  for (std::uint32_t k = 0; k < ids.size(); ++k) any_large |= size[k] >= min_cluster;
  if (!any_large) return;
  for (std::uint32_t k = 0; k < ids.size(); ++k) {
    if (within[k] >= min_cluster) continue;
    const std::uint32_t r = find_root(up, k);
    if (!large[r] && size[r] < min_cluster) stray[k] = 1;
  }
}

// Both rules over the kept points with the reach known (`reach` is called once, with the median
// spacing when `spacing` is set, else with 0).
std::size_t drop(const std::vector<Eigen::Vector3d>& pts, std::vector<std::uint8_t>& keep,
                 const std::function<double(double)>& reach, bool spacing, StrayRule rule) {
  const std::size_t min_others = std::size_t(std::max(rule.min_neighbours, 0));
  if (min_others == 0 && rule.min_cluster <= 1) return 0;
  const std::vector<std::uint32_t> ids = kept_ids(keep);
  if (ids.size() < 2 || ids.size() <= min_others) return 0;
  const PointIndex index(pts, ids);
  // Each kept point's `want` nearest (itself first): the squared distance of its nearest other
  // (the median spacing's sample) and of the last (the neighbour test).
  const std::size_t want = std::max<std::size_t>(min_others + 1, spacing ? 2 : 1);
  std::vector<double> nearest2(ids.size(), -1.0), last2(ids.size(), -1.0);
  if (want >= 2) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ids.size()),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        std::vector<std::uint32_t> near(want);
                        std::vector<double> d2(want);
                        for (std::size_t k = range.begin(); k != range.end(); ++k) {
                          const std::size_t n =
                              index.knn(pts[ids[k]], want, near.data(), d2.data());
                          if (n >= 2) nearest2[k] = d2[1];
                          if (n == want) last2[k] = d2[want - 1];
                        }
                      });
  }
  double median = 0;
  if (spacing) {
    // The median of the nearest others' distances over median_spacing's sample.
    std::vector<double> d;
    const std::size_t stride = std::max<std::size_t>(1, ids.size() / 4000);
    for (std::size_t k = 0; k < ids.size(); k += stride) {
      if (nearest2[k] >= 0) d.push_back(std::sqrt(nearest2[k]));
    }
    if (d.empty()) return 0;
    std::nth_element(d.begin(), d.begin() + std::ptrdiff_t(d.size() / 2), d.end());
    median = d[d.size() / 2];
  }
  const double radius = reach(median);
  if (!(radius > 0)) return 0;
  std::vector<std::uint8_t> stray(ids.size(), 0);
  if (min_others > 0) {
    for (std::size_t k = 0; k < ids.size(); ++k)
      stray[k] = last2[k] < 0 || !(last2[k] < radius * radius);
  }
  if (rule.min_cluster > 1) mark_small_clusters(pts, ids, index, radius, rule.min_cluster, stray);
  std::size_t dropped = 0;
  for (std::size_t k = 0; k < ids.size(); ++k) {
    if (stray[k]) keep[ids[k]] = 0, ++dropped;
  }
  return dropped;
}

}  // namespace

std::size_t drop_stray_points(const std::vector<Eigen::Vector3d>& pts,
                              std::vector<std::uint8_t>& keep, double radius, StrayRule rule) {
  return drop(
      pts, keep, [radius](double) { return radius; }, false, rule);
}

std::size_t drop_stray_points(const std::vector<Eigen::Vector3d>& pts,
                              std::vector<std::uint8_t>& keep,
                              const std::function<double(double)>& reach, StrayRule rule) {
  return drop(pts, keep, reach, true, rule);
}

void StrayPasses::alone(const std::vector<Eigen::Vector3d>& pts, std::vector<std::uint8_t>& keep,
                        const std::function<double(double)>& reach) {
  dropped_ += drop_stray_points(pts, keep, [&](double spacing) { return reach_ = reach(spacing); },
                                {rule_.min_neighbours, 0});
}

void StrayPasses::clusters(const std::vector<Eigen::Vector3d>& pts,
                           std::vector<std::uint8_t>& keep) {
  if (reach_ > 0) dropped_ += drop_stray_points(pts, keep, reach_, {0, rule_.min_cluster});
}

std::string StrayPasses::note(const std::string& unit) const {
  const int n = rule_.min_neighbours;
  std::string s = "ignored " + std::to_string(dropped_) + " stray point(s): ";
  if (n > 0) {
    s += "fewer than " +
         (n == 1   ? std::string("one other")
          : n == 2 ? std::string("two others")
                   : std::to_string(n) + " others") +
         " within four " + unit;
  }
  if (rule_.min_cluster > 1) {
    s += (n > 0 ? ", or " : "") + std::string("in a cluster of fewer than ") +
         std::to_string(rule_.min_cluster) + " points";
  }
  return s;
}

}  // namespace ramus::bsg
