// An exactly self-similar voxel shape for the voxel-grammar and spanning-tree tests: a cell is
// occupied when at every scale its octant (dx + 2dy + 4dz) has even parity (0, 3, 5 or 6), a 3D
// Sierpinski pattern. Its next level is known exactly, the ground truth for super-resolution.
#pragma once

#include "infer/wavelet/voxel_grid.h"

namespace ramus::wavelet::test {

inline VoxelGrid sierpinski(int levels) {
  VoxelGrid g(levels);
  for (std::size_t z = 0; z < g.n; ++z) {
    for (std::size_t y = 0; y < g.n; ++y) {
      for (std::size_t x = 0; x < g.n; ++x) {
        bool on = true;
        for (int b = 0; b < levels; ++b) {
          on = on && (((x ^ y ^ z) >> b) & 1) == 0;
        }
        g.at(x, y, z) = on ? 1.0 : 0.0;
      }
    }
  }
  return g;
}

}  // namespace ramus::wavelet::test
