#include "reconstruct/bsg/stray_points.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "reconstruct/bsg/kdtree.h"

namespace ramus::bsg {

namespace {

// The search behind both overloads: each kept point's `want` nearest kept points (itself
// first), their squared distances in d2[k * want ...], and the ids of the kept points.
struct Neighbours {
  std::vector<std::uint32_t> ids;
  std::vector<double> d2;
  std::vector<std::uint32_t> found;  // how many of the `want` each search found
};

Neighbours nearest(const std::vector<Eigen::Vector3d>& pts, const std::vector<std::uint8_t>& keep,
                   std::size_t want) {
  Neighbours n;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (keep[i]) n.ids.push_back(std::uint32_t(i));
  }
  if (n.ids.size() < want) return n;
  const PointIndex index(pts, n.ids);
  n.d2.assign(n.ids.size() * want, 0.0);
  n.found.assign(n.ids.size(), 0);
  auto search = [&](const tbb::blocked_range<std::size_t>& range) {
    std::vector<std::uint32_t> near(want);
    for (std::size_t k = range.begin(); k != range.end(); ++k) {
      n.found[k] = std::uint32_t(index.knn(pts[n.ids[k]], want, near.data(), &n.d2[k * want]));
    }
  };
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n.ids.size()), search);
  return n;
}

// Clears keep[] for the points with fewer than `want` (themselves included) within `radius`.
std::size_t drop(const Neighbours& n, std::size_t want, double radius,
                 std::vector<std::uint8_t>& keep) {
  if (n.found.empty() || !(radius > 0)) return 0;
  const double r2 = radius * radius;
  std::size_t dropped = 0;
  for (std::size_t k = 0; k < n.ids.size(); ++k) {
    std::size_t within = 0;
    for (std::size_t j = 0; j < n.found[k]; ++j) within += n.d2[k * want + j] < r2 ? 1 : 0;
    if (within < want) keep[n.ids[k]] = 0, ++dropped;
  }
  return dropped;
}

}  // namespace

std::size_t drop_stray_points(const std::vector<Eigen::Vector3d>& pts,
                              std::vector<std::uint8_t>& keep, double radius, int min_neighbours) {
  if (!(radius > 0) || min_neighbours <= 0) return 0;
  const std::size_t want = std::size_t(min_neighbours) + 1;  // the point itself is found too
  const Neighbours n = nearest(pts, keep, want);
  if (n.ids.size() <= std::size_t(min_neighbours)) return 0;
  return drop(n, want, radius, keep);
}

std::size_t drop_stray_points(const std::vector<Eigen::Vector3d>& pts,
                              std::vector<std::uint8_t>& keep,
                              const std::function<double(double)>& reach, int min_neighbours) {
  if (min_neighbours <= 0) return 0;
  const std::size_t want = std::size_t(min_neighbours) + 1;  // >= 2: the nearest other too
  const Neighbours n = nearest(pts, keep, want);
  if (n.ids.size() <= std::size_t(min_neighbours)) return 0;
  // The median of the nearest others' distances over median_spacing's sample.
  std::vector<double> d;
  const std::size_t stride = std::max<std::size_t>(1, n.ids.size() / 4000);
  for (std::size_t k = 0; k < n.ids.size(); k += stride) {
    if (n.found[k] >= 2) d.push_back(std::sqrt(n.d2[k * want + 1]));
  }
  if (d.empty()) return 0;
  std::nth_element(d.begin(), d.begin() + std::ptrdiff_t(d.size() / 2), d.end());
  return drop(n, want, reach(d[d.size() / 2]), keep);
}

}  // namespace ramus::bsg
