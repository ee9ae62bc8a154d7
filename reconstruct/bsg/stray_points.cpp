#include "reconstruct/bsg/stray_points.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "reconstruct/bsg/kdtree.h"

namespace ramus::bsg {

std::size_t drop_stray_points(const std::vector<Eigen::Vector3d>& pts,
                              std::vector<std::uint8_t>& keep, double radius, int min_neighbours) {
  return drop_stray_points(
      pts, keep, [radius](double) { return radius; }, min_neighbours);
}

std::size_t drop_stray_points(const std::vector<Eigen::Vector3d>& pts,
                              std::vector<std::uint8_t>& keep,
                              const std::function<double(double)>& reach, int min_neighbours) {
  if (min_neighbours <= 0) return 0;
  std::vector<std::uint32_t> ids;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (keep[i]) ids.push_back(std::uint32_t(i));
  }
  if (ids.size() <= std::size_t(min_neighbours)) return 0;
  // Each kept point's `want` nearest kept points (itself first): their squared distances in
  // d2[k * want ...], how many were found in found[k].
  const std::size_t want = std::size_t(min_neighbours) + 1;  // >= 2: the nearest other too
  const PointIndex index(pts, ids);
  std::vector<double> d2(ids.size() * want, 0.0);
  std::vector<std::uint32_t> found(ids.size(), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ids.size()),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      std::vector<std::uint32_t> near(want);
                      for (std::size_t k = range.begin(); k != range.end(); ++k) {
                        found[k] =
                            std::uint32_t(index.knn(pts[ids[k]], want, near.data(), &d2[k * want]));
                      }
                    });
  // The median of the nearest others' distances over median_spacing's sample.
  std::vector<double> d;
  const std::size_t stride = std::max<std::size_t>(1, ids.size() / 4000);
  for (std::size_t k = 0; k < ids.size(); k += stride) {
    if (found[k] >= 2) d.push_back(std::sqrt(d2[k * want + 1]));
  }
  if (d.empty()) return 0;
  std::nth_element(d.begin(), d.begin() + std::ptrdiff_t(d.size() / 2), d.end());
  const double radius = reach(d[d.size() / 2]);
  if (!(radius > 0)) return 0;
  const double r2 = radius * radius;
  std::size_t dropped = 0;
  for (std::size_t k = 0; k < ids.size(); ++k) {
    std::size_t within = 0;
    for (std::size_t j = 0; j < found[k]; ++j) within += d2[k * want + j] < r2 ? 1 : 0;
    if (within < want) keep[ids[k]] = 0, ++dropped;
  }
  return dropped;
}

}  // namespace ramus::bsg
