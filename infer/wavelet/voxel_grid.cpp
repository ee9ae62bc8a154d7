#include "infer/wavelet/voxel_grid.h"

#include <string>

namespace ramus::wavelet {

int levels_for_side(std::uint64_t n) {
  if (!is_power_of_two(n) || n > (std::uint64_t(1) << kMaxLevels)) {
    throw std::invalid_argument("grid side " + std::to_string(n) +
                                " is not a power of two between 1 and " +
                                std::to_string(1u << kMaxLevels));
  }
  int levels = 0;
  while ((std::uint64_t(1) << levels) < n) ++levels;
  return levels;
}

VoxelGrid::VoxelGrid(int levels_) {
  if (levels_ < 0 || levels_ > kMaxLevels) {
    throw std::invalid_argument("grid level " + std::to_string(levels_) + " is outside [0, " +
                                std::to_string(kMaxLevels) + "]");
  }
  levels = levels_;
  n = std::size_t(1) << levels;
  values.assign(n * n * n, 0.0);
}

std::size_t VoxelGrid::count_above(double threshold) const {
  std::size_t c = 0;
  for (double v : values) c += v > threshold ? 1 : 0;
  return c;
}

double voxel_iou(const VoxelGrid& a, double ta, const VoxelGrid& b, double tb) {
  if (a.n != b.n) {
    throw std::invalid_argument("voxel_iou: grids of side " + std::to_string(a.n) + " and " +
                                std::to_string(b.n));
  }
  std::size_t inter = 0, uni = 0;
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    bool pa = a.values[i] > ta, pb = b.values[i] > tb;
    inter += pa && pb;
    uni += pa || pb;
  }
  return uni == 0 ? 1.0 : double(inter) / double(uni);
}

VoxelGrid upsample_nearest(const VoxelGrid& g) {
  VoxelGrid out(g.levels + 1);
  out.origin = g.origin;
  out.voxel_size = g.voxel_size / 2;
  for (std::size_t z = 0; z < out.n; ++z) {
    for (std::size_t y = 0; y < out.n; ++y) {
      for (std::size_t x = 0; x < out.n; ++x) out.at(x, y, z) = g.at(x / 2, y / 2, z / 2);
    }
  }
  return out;
}

}  // namespace ramus::wavelet
