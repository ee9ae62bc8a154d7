#include "reconstruct/bsg/stray_points.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "reconstruct/bsg/kdtree.h"

namespace ramus::bsg {

std::size_t drop_stray_points(const std::vector<Eigen::Vector3d>& pts,
                              std::vector<std::uint8_t>& keep, double radius, int min_neighbours) {
  if (!(radius > 0) || min_neighbours <= 0) return 0;
  std::vector<std::uint32_t> ids;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (keep[i]) ids.push_back(std::uint32_t(i));
  }
  if (ids.size() <= std::size_t(min_neighbours)) return 0;
  const PointIndex index(pts, ids);
  std::vector<std::uint8_t> stray(ids.size(), 0);
  const std::size_t want = std::size_t(min_neighbours) + 1;  // the point itself is found too
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ids.size()),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      std::vector<std::uint32_t> found(want);
                      std::vector<double> d2(want);
                      for (std::size_t k = range.begin(); k != range.end(); ++k) {
                        const std::size_t n =
                            index.knn_within(pts[ids[k]], want, radius, found.data(), d2.data());
                        stray[k] = n < want ? 1 : 0;
                      }
                    });
  std::size_t dropped = 0;
  for (std::size_t k = 0; k < ids.size(); ++k) {
    if (stray[k]) keep[ids[k]] = 0, ++dropped;
  }
  return dropped;
}

}  // namespace ramus::bsg
