// Quantizing an aligned cloud into a 2^L cube (Friedman & Stamos 2013, III-A).
//
// The cube is the smallest axis-aligned cube that holds every point, grown by a relative margin
// of 1e-9 so the extreme points fall inside: its bottom face is at the root's height (z = 0 in the
// aligned frame), and it is centred horizontally on the cloud's bounding box. All points of a
// degenerate cloud (one point, all points within 1e-9 m) fall into one voxel of a cube of side
// `min_extent`.
#pragma once

#include <string>

#include "infer/wavelet/alignment.h"
#include "infer/wavelet/voxel_grid.h"

namespace ramus::wavelet {

enum class VoxelValues {
  occupancy,  // 1 where a voxel holds at least one point, else 0
  density,    // points in the voxel / points in the fullest voxel: in [0, 1], 1 somewhere
};

// Parses "occupancy" / "density"; throws std::invalid_argument naming the bad word.
VoxelValues parse_voxel_values(const std::string& word);
const char* to_string(VoxelValues v);

struct VoxelizeOptions {
  int levels = 6;  // side 2^levels: 6 -> 64^3 (the paper's default), 7 -> 128^3
  VoxelValues values = VoxelValues::occupancy;
  double min_extent = 1e-3;  // cube side used when the cloud has no extent
};

// Throws std::invalid_argument for an empty cloud or levels outside [0, kMaxLevels].
VoxelGrid voxelize(const AlignedCloud& cloud, const VoxelizeOptions& options);

// The other way: one point at the centre of every voxel whose value exceeds `threshold`, in world
// coordinates through `alignment` (offset = the root), or in the grid's frame when it is null.
PointCloud voxel_centres(const VoxelGrid& grid, double threshold,
                         const Alignment* alignment = nullptr);

}  // namespace ramus::wavelet
