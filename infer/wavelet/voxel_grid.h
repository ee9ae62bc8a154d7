// VoxelGrid: the dense, power-of-two cube of values that the wavelet method works on
// (Friedman & Stamos 2013, III-A "Quantization").
//
// A grid has side n = 2^levels and stores one double per voxel, x fastest:
// index(x, y, z) = x + n * (y + n * z). `origin` is the corner of voxel (0,0,0) and `voxel_size`
// the edge of a voxel, both in the frame the grid was made in (for scans: the aligned frame of
// alignment.h, metres, z up). Wavelet coefficient arrays use the same type and layout.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "core/vec3.h"

namespace ramus::wavelet {

// The largest grid this code accepts: 2^9 = 512 per side is 1 GiB of doubles per grid, and the
// transform and the compression figures hold a few grids at once.
inline constexpr int kMaxLevels = 9;

constexpr bool is_power_of_two(std::uint64_t n) { return n != 0 && (n & (n - 1)) == 0; }

// log2 of a power of two n in [1, 2^kMaxLevels]; throws std::invalid_argument otherwise, with
// a message that names the value (used for user-facing `--grid` values too).
int levels_for_side(std::uint64_t n);

struct VoxelGrid {
  int levels = 0;     // side n = 2^levels
  std::size_t n = 1;  // side length in voxels
  std::vector<double> values;
  Vec3 origin{0, 0, 0};  // corner of voxel (0,0,0)
  double voxel_size = 1.0;

  VoxelGrid() : values(1, 0.0) {}
  // A zero grid of side 2^levels; throws std::invalid_argument for levels outside [0, kMaxLevels].
  explicit VoxelGrid(int levels_);

  std::size_t size() const { return values.size(); }
  std::size_t index(std::size_t x, std::size_t y, std::size_t z) const {
    return x + n * (y + n * z);
  }
  double& at(std::size_t x, std::size_t y, std::size_t z) { return values[index(x, y, z)]; }
  double at(std::size_t x, std::size_t y, std::size_t z) const { return values[index(x, y, z)]; }
  // Centre of voxel (x, y, z) in the grid's frame.
  Vec3 centre(double x, double y, double z) const {
    return origin + Vec3(x + 0.5, y + 0.5, z + 0.5) * voxel_size;
  }

  std::size_t count_above(double threshold) const;
};

// Intersection over union of the voxel sets {a > ta} and {b > tb}; 1 when both are empty.
// The grids must have the same side (std::invalid_argument otherwise).
double voxel_iou(const VoxelGrid& a, double ta, const VoxelGrid& b, double tb);

// Plain nearest-neighbour upsampling: every voxel becomes 2x2x2 voxels of the same value, the
// baseline the super-resolution of III-D is compared with (paper, Figures 6-7).
VoxelGrid upsample_nearest(const VoxelGrid& g);

}  // namespace ramus::wavelet
