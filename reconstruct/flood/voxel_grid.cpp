#include "reconstruct/flood/voxel_grid.h"

#include <algorithm>
#include <cmath>

namespace ramus::flood {

std::uint64_t VoxelGrid::key(std::int64_t x, std::int64_t y, std::int64_t z) {
  // 21 bits per axis: 2 million voxels along each side is far beyond any useful grid.
  constexpr std::int64_t mask = (std::int64_t(1) << 21) - 1;
  return (std::uint64_t(x & mask) << 42) | (std::uint64_t(y & mask) << 21) |
         std::uint64_t(z & mask);
}

VoxelGrid::VoxelGrid(const std::vector<Vec3>& points, const std::vector<std::uint8_t>& keep,
                     double size)
    : edge_(size) {
  point_voxel_.assign(points.size(), kNoVoxel);
  Vec3 lo{1e300, 1e300, 1e300};
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!keep[i]) continue;
    lo = {std::min(lo.x, points[i].x), std::min(lo.y, points[i].y), std::min(lo.z, points[i].z)};
  }
  // Alg. 2 lines 5-9: V = (P - min) / edge, with one edge for all three axes (cubic voxels).
  struct Entry {
    std::uint64_t key;
    std::uint32_t point;
    std::int32_t x, y, z;
  };
  std::vector<Entry> entries;
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    if (!keep[i]) continue;
    const auto cx = std::int32_t(std::min(std::floor((points[i].x - lo.x) / edge_), 2.0e6));
    const auto cy = std::int32_t(std::min(std::floor((points[i].y - lo.y) / edge_), 2.0e6));
    const auto cz = std::int32_t(std::min(std::floor((points[i].z - lo.z) / edge_), 2.0e6));
    entries.push_back({key(cx, cy, cz), i, cx, cy, cz});
  }
  std::stable_sort(entries.begin(), entries.end(),
                   [](const Entry& a, const Entry& b) { return a.key < b.key; });
  members_.reserve(entries.size());
  for (std::size_t k = 0; k < entries.size(); ++k) {
    if (k == 0 || entries[k].key != entries[k - 1].key) {
      index_.emplace(entries[k].key, std::uint32_t(first_.size()));
      first_.push_back(std::uint32_t(members_.size()));
      cells_.insert(cells_.end(), {entries[k].x, entries[k].y, entries[k].z});
    }
    point_voxel_[entries[k].point] = std::uint32_t(first_.size() - 1);
    members_.push_back(entries[k].point);
  }
  first_.push_back(std::uint32_t(members_.size()));
}

std::uint32_t VoxelGrid::neighbour(std::uint32_t v, int dx, int dy, int dz) const {
  const std::int64_t x = cells_[3 * v] + dx, y = cells_[3 * v + 1] + dy, z = cells_[3 * v + 2] + dz;
  if (x < 0 || y < 0 || z < 0) return kNoVoxel;
  const auto it = index_.find(key(x, y, z));
  return it == index_.end() ? kNoVoxel : it->second;
}

}  // namespace ramus::flood
