// Stray points: returns that lie alone in the air. A beam wider than a twig returns from its
// edge and from what lies behind it at once, and a scanner that cannot part the two echoes puts a
// point between them ("mixed pixels"; wind, a bird, dust do the same). They are a few percent of
// a scan (2% of thick_oak scanned with a 0.3 mrad beam, `ramus scan --beam-divergence`), but the
// gap bridging joins each to the nearest tree, and every one becomes a branch: the skeleton was
// twice the true length and its precision within 2 x radius 0.74 instead of 0.998. A point of a
// surface has neighbours on that surface; one with fewer than two other points within four point
// spacings supports no branch, and it is ignored. docs/reconstruction.md, "Stray points".
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace ramus::bsg {

// What makes a point stray. Mixed pixels also come in runs of a few (the neighbouring beams of
// one scan line at the same twig edge): three points 1.5 cm apart, alone in the air, each with
// two others within reach. A cluster (points linked by steps within the reach) that small is no
// branch either: the gap bridging chained such runs into branches through the air (the weeping
// tree scanned with a 0.3 mrad beam from three stations). Runs are mostly three or four points;
// bark seen through a gap in the crown makes clusters of every size (docs/reconstruction.md,
// "Runs of a few": 5 is what was measured best; the pipelines leave it off by default).
struct StrayRule {
  int min_neighbours = 2;       // fewer other points than this within the reach: stray
  std::size_t min_cluster = 1;  // in a cluster of fewer points than this: stray (1: none)
};

// Clears keep[i] for every stray kept point: fewer than `rule.min_neighbours` other kept points
// within `radius` (duplicates of it count), or in a cluster of fewer than `rule.min_cluster`
// kept points linked by steps shorter than `radius`. Judged against the points kept on entry
// (one pass: what a stray leaves alone is not dropped in turn). Nothing is dropped when no more
// than `rule.min_neighbours` points are kept, and no cluster is dropped for its size when none
// is as large as `rule.min_cluster`. Returns the number of points dropped.
std::size_t drop_stray_points(const std::vector<Eigen::Vector3d>& pts,
                              std::vector<std::uint8_t>& keep, double radius, StrayRule rule = {});

// The same with the reach set from the points themselves: `reach(spacing)` of the median
// distance from a kept point to its nearest other (over the strided sample of median_spacing in
// kdtree.h, the same value). One k-d tree serves both (the pipeline's whole-cloud voxel cost a
// second tree and search, 2 ms of a 40 ms airborne scan).
std::size_t drop_stray_points(const std::vector<Eigen::Vector3d>& pts,
                              std::vector<std::uint8_t>& keep,
                              const std::function<double(double)>& reach, StrayRule rule = {});

// The two passes of the pipelines (the BSG's and the flood fill's): the points alone in the air
// before the tree bases, which are found on the points the graph is built from, with the reach
// from the median spacing; the small clusters after the terrain, with the same reach, so that
// the bases are found as without them (the ground's clutter is small clusters too: dropped before
// the bases, treels_spruce's base moved 0.4 m off its trunk). docs/reconstruction.md, "Stray
// points", "Runs of a few".
class StrayPasses {
 public:
  explicit StrayPasses(StrayRule rule) : rule_(rule) {}
  // The neighbour test; `reach(spacing)` as in drop_stray_points.
  void alone(const std::vector<Eigen::Vector3d>& pts, std::vector<std::uint8_t>& keep,
             const std::function<double(double)>& reach);
  // The cluster test, with alone()'s reach (nothing when alone() did not run).
  void clusters(const std::vector<Eigen::Vector3d>& pts, std::vector<std::uint8_t>& keep);
  std::size_t dropped() const { return dropped_; }
  // "ignored N stray point(s): fewer than two others within four <unit>[, or in a cluster of
  // fewer than 5 points]"; `unit` names what the reach is four of.
  std::string note(const std::string& unit) const;

 private:
  StrayRule rule_;
  double reach_ = 0;
  std::size_t dropped_ = 0;
};

}  // namespace ramus::bsg
