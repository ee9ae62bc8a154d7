// Where the wood of a dyad's cells is: the centroid of the scan points each cell covers.
//
// Friedman & Stamos 2013 (III-E) place the nodes of a dyad's spanning tree on the grid: "the
// weights are set to the Euclidean distances between the voxel grid coordinates". Grid
// coordinates make every edge a lattice offset, so a tree regrown from them runs along the
// axes (40-87 % of its length within 3 degrees of x, y or z on the bundled scans). The cell
// stays the node (its coefficient is what III-E thresholds); only its *position* is taken from
// the data: the mean of the points inside the region of space the cell covers, which is where
// the wood is, to a fraction of a cell, and no longer on the lattice. Every occupied cell of
// every dyad is kept, so that links across cells without a significant coefficient can follow
// the points too (tree_hierarchy.h).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "core/vec3.h"
#include "infer/wavelet/alignment.h"
#include "infer/wavelet/voxel_grid.h"

namespace ramus::wavelet {

class CellCentroids {
 public:
  // One pass over the points into the cells of the finest dyad of `grid` (the grid they were
  // voxelized into), then each coarser dyad by merging eight cells into one.
  CellCentroids(const AlignedCloud& cloud, const VoxelGrid& grid);

  // The centroid of the points in cell `cell` (local index, 0 .. 2^level - 1 per axis) of dyad
  // `level` (0 .. L-1), aligned frame; nothing when the cell holds no point.
  std::optional<Vec3> centroid(int level, const std::array<int, 3>& cell) const;
  // The centre of that cell.
  Vec3 centre(int level, const std::array<int, 3>& cell) const;
  // The cell of dyad `level` holding point p (clamped into the grid like voxelize()).
  std::array<int, 3> cell_of(int level, const Vec3& p) const;

 private:
  struct Sum {
    Vec3 sum{0, 0, 0};
    std::uint32_t count = 0;
  };
  const VoxelGrid& grid_;
  std::vector<std::unordered_map<std::uint64_t, Sum>> levels_;  // index: dyad 0 .. L-1
};

}  // namespace ramus::wavelet
