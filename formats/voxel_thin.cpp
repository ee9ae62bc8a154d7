#include "formats/voxel_thin.h"

#include <algorithm>
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
  const bool added = insert(c);
  if (added && journal_) added_.push_back(c);
  return added;
}

bool VoxelThinner::keep(const Vec3& offset, const Vec3f& position) {
  return keep(offset + Vec3(position));
}

bool VoxelThinner::packed(const Cell& c, std::uint64_t& key) const {
  const std::int64_t d[3] = {c.x - base_.x, c.y - base_.y, c.z - base_.z};
  key = 0;
  for (int k = 0; k < 3; ++k) {
    if (d[k] < -kReach || d[k] >= kReach) return false;
    key |= std::uint64_t(d[k] + kReach) << (21 * k);
  }
  return true;
}

bool VoxelThinner::insert(const Cell& c) {
  if (!based_) {
    base_ = c;
    based_ = true;
  }
  std::uint64_t key;
  if (packed(c, key)) return insert_packed(key);
  return far_.insert(c).second;
}

void VoxelThinner::erase(const Cell& c) {
  std::uint64_t key;
  if (packed(c, key)) {
    erase_packed(key);
  } else {
    far_.erase(c);
  }
}

bool VoxelThinner::insert_packed(std::uint64_t key) {
  if (2 * (packed_count_ + 1) > table_.size()) grow();
  const std::size_t mask = table_.size() - 1;
  for (std::size_t i = std::size_t(mix64(key)) & mask;; i = (i + 1) & mask) {
    if (table_[i] == key + 1) return false;
    if (table_[i] == 0) {
      table_[i] = key + 1;
      ++packed_count_;
      return true;
    }
  }
}

// Deletion by backward shift (Knuth 6.4, algorithm R): the entries after the hole that probed
// past it move into it, so lookups never stop early at a hole.
void VoxelThinner::erase_packed(std::uint64_t key) {
  if (table_.empty()) return;
  const std::size_t mask = table_.size() - 1;
  std::size_t i = std::size_t(mix64(key)) & mask;
  while (table_[i] != key + 1) {
    if (table_[i] == 0) return;
    i = (i + 1) & mask;
  }
  --packed_count_;
  for (std::size_t j = (i + 1) & mask; table_[j] != 0; j = (j + 1) & mask) {
    const std::size_t home = std::size_t(mix64(table_[j] - 1)) & mask;
    // j's entry may fill the hole at i when its home is not cyclically within (i, j].
    const bool stays = i <= j ? (i < home && home <= j) : (i < home || home <= j);
    if (stays) continue;
    table_[i] = table_[j];
    i = j;
  }
  table_[i] = 0;
}

void VoxelThinner::grow() {
  std::vector<std::uint64_t> old(std::max<std::size_t>(1024, 2 * table_.size()), 0);
  old.swap(table_);
  packed_count_ = 0;
  for (std::uint64_t stored : old) {
    if (stored != 0) insert_packed(stored - 1);
  }
}

void VoxelThinner::mark() {
  journal_ = true;
  added_.clear();
}

void VoxelThinner::undo_since_mark() {
  for (const Cell& c : added_) erase(c);
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
