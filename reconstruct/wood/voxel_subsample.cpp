#include "reconstruct/wood/voxel_subsample.h"

#include <cmath>
#include <unordered_map>

namespace ramus::wood {

VoxelSubsample voxel_subsample(const std::vector<Eigen::Vector3d>& pts,
                               const std::vector<std::uint8_t>& keep, double size) {
  VoxelSubsample v;
  v.cell.assign(pts.size(), VoxelSubsample::kNoCell);
  // 21 bits per axis: cells are addressed relative to the grid's lowest corner, which covers
  // 2 million cells per axis, far more than any scan at a sensible scale needs.
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (keep.empty() || keep[i]) lo = lo.cwiseMin(pts[i]);
  }
  std::unordered_map<std::uint64_t, std::uint32_t> index;
  std::vector<Eigen::Vector3d> sum;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (!keep.empty() && !keep[i]) continue;
    std::uint64_t key = 0;
    for (int k = 0; k < 3; ++k) {
      const double c = std::floor((pts[i][k] - lo[k]) / size);
      key = (key << 21) | (std::uint64_t(std::min(c, double((1 << 21) - 1))) & ((1u << 21) - 1));
    }
    auto [it, added] = index.try_emplace(key, std::uint32_t(sum.size()));
    if (added) {
      sum.push_back(Eigen::Vector3d::Zero());
      v.count.push_back(0);
    }
    sum[it->second] += pts[i];
    ++v.count[it->second];
    v.cell[i] = it->second;
  }
  v.centroids.resize(sum.size());
  for (std::size_t c = 0; c < sum.size(); ++c) v.centroids[c] = sum[c] / double(v.count[c]);
  return v;
}

}  // namespace ramus::wood
