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
  std::size_t cells() const { return cells_.size(); }
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
  double size_, inverse_;
  std::unordered_set<Cell, CellHash> cells_;
  bool journal_ = false;
  std::vector<Cell> added_;  // since mark(), while journal_
};

// `cloud` with only the first point of each cube kept, with its channels (normals, intensity,
// classification); the offset, scanner and source stay.
PointCloud thin_cloud(const PointCloud& cloud, double size);

}  // namespace ramus
