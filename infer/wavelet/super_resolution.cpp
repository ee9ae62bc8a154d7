#include "infer/wavelet/super_resolution.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace ramus::wavelet {

VoxelGrid super_resolve_with(const VoxelGrid& grid, const VoxelGrammar& grammar,
                             const SuperResolutionOptions& options) {
  if (grid.levels < 2 || grid.levels + 1 > kMaxLevels) {
    throw std::invalid_argument("super-resolution needs a grid of side 4 to " +
                                std::to_string(1 << (kMaxLevels - 1)) + ", not " +
                                std::to_string(grid.n));
  }
  WaveletPyramid pyramid = haar_forward(grid, Decomposition::nonstandard);
  std::vector<VoxelGrid> approximations = approximation_levels(grid);
  const std::size_t n = grid.n;
  VoxelGrid big(grid.levels + 1);
  big.origin = grid.origin;
  big.voxel_size = grid.voxel_size / 2;
  // The approximation of the new top level is the input itself.
  for (std::size_t z = 0; z < n; ++z) {
    for (std::size_t y = 0; y < n; ++y) {
      for (std::size_t x = 0; x < n; ++x) big.at(x, y, z) = grid.at(x, y, z);
    }
  }
  for (int s = 1; s <= 7; ++s) {
    std::vector<double> details =
        synthesize_subband(grammar, pyramid, approximations, grid.levels - 1, s, options.seed);
    const std::size_t ox = s & 1 ? n : 0, oy = s & 2 ? n : 0, oz = s & 4 ? n : 0;
    for (std::size_t z = 0; z < n; ++z) {
      for (std::size_t y = 0; y < n; ++y) {
        for (std::size_t x = 0; x < n; ++x) {
          // Detail (x, y, z) of the new level refines input voxel (x, y, z).
          const double mean = grid.at(x, y, z);
          if (options.support_only && mean == 0.0) continue;
          const double d = details[x + n * (y + n * z)];
          big.at(ox + x, oy + y, oz + z) = grammar.relative ? d * mean : d;
        }
      }
    }
  }
  haar_inverse_step_nonstandard(big, n);
  return big;
}

SuperResolution super_resolve(const VoxelGrid& grid, const SuperResolutionOptions& options) {
  if (grid.levels < 2) {
    throw std::invalid_argument("super-resolution needs a grid of side 4 or more, not " +
                                std::to_string(grid.n));
  }
  SuperResolution out;
  VoxelGrammarOptions vo;
  vo.classes = options.classes;
  vo.relative = options.relative;
  out.grammar = learn_voxel_grammar(haar_forward(grid, Decomposition::nonstandard),
                                    approximation_levels(grid), vo);
  out.grid = super_resolve_with(grid, out.grammar, options);
  return out;
}

std::size_t surface_voxels(const VoxelGrid& g, double threshold) {
  const std::size_t n = g.n;
  auto occupied = [&](std::size_t x, std::size_t y, std::size_t z) {
    return x < n && y < n && z < n && g.at(x, y, z) > threshold;  // wraps below 0 to >= n
  };
  std::size_t count = 0;
  for (std::size_t z = 0; z < n; ++z) {
    for (std::size_t y = 0; y < n; ++y) {
      for (std::size_t x = 0; x < n; ++x) {
        if (!occupied(x, y, z)) continue;
        bool inner = occupied(x - 1, y, z) && occupied(x + 1, y, z) && occupied(x, y - 1, z) &&
                     occupied(x, y + 1, z) && occupied(x, y, z - 1) && occupied(x, y, z + 1);
        count += inner ? 0 : 1;
      }
    }
  }
  return count;
}

ResolutionComparison compare_resolutions(const VoxelGrid& coarse, const VoxelGrid& enhanced,
                                         const VoxelGrid& truth, double threshold) {
  if (enhanced.n != truth.n || enhanced.n != 2 * coarse.n) {
    throw std::invalid_argument(
        "compare_resolutions: the enhanced grid and the truth must have "
        "twice the side of the coarse grid");
  }
  VoxelGrid up = upsample_nearest(coarse);
  ResolutionComparison c;
  c.iou_enhanced = voxel_iou(enhanced, threshold, truth, 0.0);
  c.iou_upsampled = voxel_iou(up, 0.0, truth, 0.0);
  c.voxels_truth = truth.count_above(0.0);
  c.voxels_enhanced = enhanced.count_above(threshold);
  c.voxels_upsampled = up.count_above(0.0);
  for (std::size_t i = 0; i < truth.size(); ++i) {
    if (!(truth.values[i] > 0)) continue;
    c.hits_enhanced += enhanced.values[i] > threshold;
    c.hits_upsampled += up.values[i] > 0;
  }
  c.surface_truth = surface_voxels(truth, 0.0);
  c.surface_enhanced = surface_voxels(enhanced, threshold);
  c.surface_upsampled = surface_voxels(up, 0.0);
  return c;
}

}  // namespace ramus::wavelet
