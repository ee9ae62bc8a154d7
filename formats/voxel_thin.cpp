#include "formats/voxel_thin.h"

#include <cmath>

#include "core/rng.h"

namespace ramus {

VoxelThinner::VoxelThinner(double size) : size_(size), inverse_(1.0 / size) {}

std::size_t VoxelThinner::CellHash::operator()(const Cell& c) const {
  return std::size_t(mix64(std::uint64_t(c.x) * 0x9e3779b97f4a7c15ULL ^
                           mix64(std::uint64_t(c.y) + 0x632be59bd9b4e019ULL) ^
                           (std::uint64_t(c.z) << 1)));
}

bool VoxelThinner::keep(const Vec3& w) {
  const Cell c{std::int64_t(std::floor(w.x * inverse_)), std::int64_t(std::floor(w.y * inverse_)),
               std::int64_t(std::floor(w.z * inverse_))};
  const bool added = cells_.insert(c).second;
  if (added && journal_) added_.push_back(c);
  return added;
}

bool VoxelThinner::keep(const Vec3& offset, const Vec3f& position) {
  return keep(offset + Vec3(position));
}

void VoxelThinner::mark() {
  journal_ = true;
  added_.clear();
}

void VoxelThinner::undo_since_mark() {
  for (const Cell& c : added_) cells_.erase(c);
  added_.clear();
}

void VoxelThinner::commit() {
  journal_ = false;
  added_ = {};
}

PointCloud thin_cloud(const PointCloud& cloud, double size) {
  PointCloud out;
  out.offset = cloud.offset;
  out.scanner = cloud.scanner;
  out.source = cloud.source;
  VoxelThinner thinner(size);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (!thinner.keep(cloud.offset, cloud.positions[i])) continue;
    out.positions.push_back(cloud.positions[i]);
    if (!cloud.normals.empty()) out.normals.push_back(cloud.normals[i]);
    if (!cloud.intensity.empty()) out.intensity.push_back(cloud.intensity[i]);
    if (!cloud.classification.empty()) out.classification.push_back(cloud.classification[i]);
  }
  return out;
}

}  // namespace ramus
