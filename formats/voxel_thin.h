// Voxel thinning: of the points falling in one cube of a regular grid (edge `size`, aligned to
// world coordinate 0 so every file and tile of a plot shares the grid), only the first one in
// reading order is kept. The cube of a point is decided on its world position as the finished
// cloud holds it (offset + float position, PointCloud::world), so thinning while a file is read
// (ReadOptions::thin, formats/point_cloud_io.h) and thinning the cloud read whole (thin_cloud)
// keep the same points, byte for byte. Fed point by point, it keeps memory proportional to the
// thinned cloud: the set of occupied cubes plus the kept points (`--thin S` of `ramus tile` and
// `ramus reconstruct`; docs/scale.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_set>
#include <vector>

#include "core/point_cloud.h"
#include "core/vec3.h"

namespace ramus {

class VoxelThinner {
 public:
  explicit VoxelThinner(double size);  // size > 0
  // True the first time a point falls in its cube (keep it), false afterwards.
  bool keep(const Vec3& world);
  // keep(offset + position) for a point of a cloud (PointCloud::world). Readers narrow a point
  // and thin it at once: given here as the float, the position cannot be optimized back to the
  // double it came from (GCC 12's SLP vectorizer at -O3 did fold the double -> float -> double
  // round trip when both sat in one function, and the reader kept other points than thin_cloud).
  bool keep(const Vec3& offset, const Vec3f& position);
  std::size_t cells() const { return packed_count_ + far_.size(); }
  double size() const { return size_; }

  // A reader that must read a file again (formats/point_cloud_io.cpp: its guess of the cloud's
  // offset was wrong) forgets the cubes its first pass took: mark() before the pass, then
  // undo_since_mark() drops every cube added since, or commit() keeps them. Between mark() and
  // either, the added cubes are listed (memory proportional to the kept points).
  void mark();
  void undo_since_mark();
  void commit();

 private:
  struct Cell {
    std::int64_t x, y, z;
    bool operator==(const Cell&) const = default;
  };
  struct CellHash {
    std::size_t operator()(const Cell& c) const;
  };
  // The cubes within 2^20 cubes of the first one along every axis (10 km at 1 cm) are packed in
  // 64 bits and kept in an open-addressing table, 8-16 bytes a cube where a node set takes
  // about 50: on a plot that thinning hardly reduces, the cube set is the larger part of memory.
  // Cubes farther out go to `far_`.
  static constexpr std::int64_t kReach = std::int64_t(1) << 20;
  bool insert(const Cell& c);
  void erase(const Cell& c);
  bool packed(const Cell& c, std::uint64_t& key) const;
  bool insert_packed(std::uint64_t key);  // key + 1 is stored, 0 marks an empty slot
  void erase_packed(std::uint64_t key);
  void grow();

  double size_, inverse_;
  bool based_ = false;
  Cell base_{0, 0, 0};
  std::vector<std::uint64_t> table_;  // power-of-two size, linear probing
  std::size_t packed_count_ = 0;
  std::unordered_set<Cell, CellHash> far_;
  bool journal_ = false;
  std::vector<Cell> added_;  // since mark(), while journal_
};

// `cloud` with only the first point of each cube kept, with its channels (normals, intensity,
// classification); the offset, scanner and source stay.
PointCloud thin_cloud(const PointCloud& cloud, double size);

}  // namespace ramus
