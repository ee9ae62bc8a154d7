// Points merged on a regular grid: one centroid per occupied cell, and the cell of every point.
// The separation computes each scale's features on a grid a quarter of that scale fine, so a
// neighbourhood holds a similar number of samples whatever the scan's density (a dense scan near
// the station would otherwise fill the neighbour cap at a fraction of the radius).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace ramus::wood {

struct VoxelSubsample {
  std::vector<Eigen::Vector3d> centroids;  // in order of first appearance in the input
  std::vector<std::uint32_t> count;        // input points per cell
  std::vector<std::uint32_t> cell;         // per input point: its cell; kNoCell when skipped
  static constexpr std::uint32_t kNoCell = 0xffffffffu;
};

// Merges pts[i] where keep[i] (all when keep is empty) on cubes of edge `size` > 0.
VoxelSubsample voxel_subsample(const std::vector<Eigen::Vector3d>& pts,
                               const std::vector<std::uint8_t>& keep, double size);

}  // namespace ramus::wood
