// Super-resolution with synthetic wavelets (Friedman & Stamos 2013, III-D).
//
// "Applying the voxel grammar to the finest level of detail gives a synthetic set of wavelets.
// [...] The reverse wavelet transform on the augmented set of wavelets yields an image at twice
// the resolution of the original." With the nonstandard decomposition this is one synthesis step:
// the input grid (side n) is the approximation, the grammar applied to the finest detail level
// (side n/2) of each of the seven subbands gives the seven detail subbands of side n, and
// haar_inverse_step_nonstandard produces the grid of side 2n.
//
// A synthetic detail of the new level refines one input voxel. With the default relative grammar
// (voxel_grammar.h) it is the drawn contrast times that voxel's value, so empty voxels stay empty.
// `support_only` enforces the same for raw grammars, whose zero class has rare non-zero rules
// (learned at surfaces) that would otherwise scatter isolated voxels through the air.
#pragma once

#include <cstdint>

#include "infer/wavelet/voxel_grammar.h"
#include "infer/wavelet/voxel_grid.h"

namespace ramus::wavelet {

struct SuperResolutionOptions {
  std::uint64_t seed = 1;
  bool support_only = true;
  int classes = kDefaultClasses;
  bool relative = true;  // see VoxelGrammarOptions
};

struct SuperResolution {
  VoxelGrammar grammar;  // learned from the input's nonstandard pyramid
  VoxelGrid grid;        // side 2n, same cube as the input
};

// Learns a voxel grammar from `grid` and applies it once. The grid needs at least 2 levels
// (4^3) to hold a pair of dyads; std::invalid_argument otherwise, or when the result would
// exceed kMaxLevels.
SuperResolution super_resolve(const VoxelGrid& grid, const SuperResolutionOptions& options = {});

// Applies an existing grammar (learned elsewhere, e.g. from another scan) to `grid`.
VoxelGrid super_resolve_with(const VoxelGrid& grid, const VoxelGrammar& grammar,
                             const SuperResolutionOptions& options = {});

// How a synthesized fine grid compares with a ground truth of the same cube and side (the finer
// voxelization of the same cloud) and with plain nearest-neighbour upsampling (III-D, Fig. 6-7).
struct ResolutionComparison {
  double iou_enhanced = 0.0;   // IoU(enhanced > threshold, truth > 0)
  double iou_upsampled = 0.0;  // IoU(upsampled > 0, truth > 0)
  std::size_t voxels_truth = 0, voxels_enhanced = 0, voxels_upsampled = 0;
  // Occupied voxels that are also occupied in the truth (precision = hits / voxels).
  std::size_t hits_enhanced = 0, hits_upsampled = 0;
  // Surface voxels: occupied voxels with at least one empty 6-neighbour (outside counts as empty).
  std::size_t surface_truth = 0, surface_enhanced = 0, surface_upsampled = 0;
};

// `coarse` is the input that was enhanced; occupancy of the enhanced grid is value > threshold.
ResolutionComparison compare_resolutions(const VoxelGrid& coarse, const VoxelGrid& enhanced,
                                         const VoxelGrid& truth, double threshold = 0.5);

// Occupied voxels with an empty 6-neighbour.
std::size_t surface_voxels(const VoxelGrid& grid, double threshold);

}  // namespace ramus::wavelet
