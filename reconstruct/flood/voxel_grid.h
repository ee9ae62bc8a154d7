// The voxel model of the flood-fill skeleton (thesis draft section 4.2.1, Alg. 2): the points of
// a cloud bucketed into cubic voxels, with the 26-neighbour lookup the flood (Alg. 3) walks.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/vec3.h"

namespace ramus::flood {

inline constexpr std::uint32_t kNoVoxel = 0xffffffffu;

class VoxelGrid {
 public:
  // Buckets points[i] for every i with keep[i] != 0 into voxels of edge `size` whose grid starts
  // at `origin` (the lower corner of the kept points).
  VoxelGrid(const std::vector<Vec3>& points, const std::vector<std::uint8_t>& keep, double size);

  std::uint32_t size() const { return std::uint32_t(cells_.size() / 3); }
  double edge() const { return edge_; }
  // Voxel holding point i, or kNoVoxel for a point that was not kept.
  std::uint32_t voxel_of_point(std::uint32_t i) const { return point_voxel_[i]; }
  // Indices of the points in voxel v.
  const std::uint32_t* begin(std::uint32_t v) const { return members_.data() + first_[v]; }
  const std::uint32_t* end(std::uint32_t v) const { return members_.data() + first_[v + 1]; }
  std::uint32_t count(std::uint32_t v) const { return first_[v + 1] - first_[v]; }
  // The non-empty voxel at integer offset (dx, dy, dz) from v, or kNoVoxel.
  std::uint32_t neighbour(std::uint32_t v, int dx, int dy, int dz) const;

 private:
  static std::uint64_t key(std::int64_t x, std::int64_t y, std::int64_t z);

  double edge_ = 1;
  std::vector<std::int32_t> cells_;  // x, y, z per voxel (flattened: 3 entries each)
  std::vector<std::uint32_t> first_, members_, point_voxel_;
  std::unordered_map<std::uint64_t, std::uint32_t> index_;
};

}  // namespace ramus::flood
