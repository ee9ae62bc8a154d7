// Voxel thinning on read: of the points falling in one cube of a regular grid (edge `size`,
// aligned to world coordinate 0 so every file and tile of a plot shares the grid), only the first
// one read is kept. Fed point by point while a file or tile is read, it keeps memory proportional
// to the thinned cloud: the set of occupied cubes plus the kept points (`--thin S` of
// `ramus tile` and `ramus reconstruct`; docs/scale.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_set>

#include "core/point_cloud.h"
#include "core/vec3.h"

namespace ramus {

class VoxelThinner {
 public:
  explicit VoxelThinner(double size);  // size > 0
  // True the first time a point falls in its cube (keep it), false afterwards.
  bool keep(const Vec3& world);
  std::size_t cells() const { return cells_.size(); }

 private:
  struct Cell {
    std::int64_t x, y, z;
    bool operator==(const Cell&) const = default;
  };
  struct CellHash {
    std::size_t operator()(const Cell& c) const;
  };
  double inverse_;
  std::unordered_set<Cell, CellHash> cells_;
};

// `cloud` with only the first point of each cube kept, with its channels (normals, intensity,
// classification); the offset, scanner and source stay.
PointCloud thin_cloud(const PointCloud& cloud, double size);

}  // namespace ramus
