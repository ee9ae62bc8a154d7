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
#include <vector>

namespace ramus::bsg {

// Clears keep[i] for every kept point with fewer than `min_neighbours` other kept points within
// `radius` (duplicates of it count), judged against the points kept on entry (one pass: what a
// stray leaves alone is not dropped in turn; nothing is dropped when no more than
// `min_neighbours` points are kept). Returns the number of points dropped.
std::size_t drop_stray_points(const std::vector<Eigen::Vector3d>& pts,
                              std::vector<std::uint8_t>& keep, double radius,
                              int min_neighbours = 2);

// The same with the reach set from the points themselves: `reach(spacing)` of the median
// distance from a kept point to its nearest other (over the strided sample of median_spacing in
// kdtree.h, the same value). One k-d tree and one search per point serve both (the pipeline's
// whole-cloud voxel cost a second tree and search, 2 ms of a 40 ms airborne scan).
std::size_t drop_stray_points(const std::vector<Eigen::Vector3d>& pts,
                              std::vector<std::uint8_t>& keep,
                              const std::function<double(double)>& reach, int min_neighbours = 2);

}  // namespace ramus::bsg
