// Minimum spanning tree in each dyad (Friedman & Stamos 2013, III-E).
//
// "Every voxel in the transform whose value is above some threshold, in our experiments we use
// 0.3, becomes a node in the graph. The weights are set to the Euclidean distances between the
// voxel grid coordinates above the threshold. Each tree is rooted at the lowest significant node
// in the dyad. [...] set the cross-sectional area of the branches according to Leonardo Da
// Vinci's [...] observation that the thickness of a branch is the sum of the thicknesses of the
// branching branches."
//
// Choices the paper leaves open, made here:
// - "Above the threshold" compares the magnitude |c|: a Haar detail's sign only says on which side
//   of its support the mass lies, and both signs mark structure.
// - The threshold is relative to the largest |c| of the dyad by default. Averaging-Haar details of
//   a sparse tree shrink at the coarse dyads (they are differences of occupied fractions), so an
//   absolute 0.3 leaves the coarse dyads empty, while the paper's figures show a tree in every
//   dyad. ThresholdMode::absolute gives the literal reading.
// - Da Vinci's rule is applied to areas: a leaf segment has area pi * leaf_radius^2 and every
//   other segment the sum of its children's, so a segment's radius is leaf_radius * sqrt(leaves).
// - "Lowest" is the smallest z; ties go to the smallest (y, x), then the first node.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/skeleton.h"
#include "infer/wavelet/alignment.h"
#include "infer/wavelet/haar.h"

namespace ramus::wavelet {

enum class ThresholdMode { relative_to_dyad_max, absolute };

struct DyadTreeOptions {
  double threshold = 0.3;
  ThresholdMode mode = ThresholdMode::relative_to_dyad_max;
  int subband = kDiagonalSubband;  // which block of level j (haar.h); 7 = the diagonal dyad
  double leaf_radius = 0.25;       // in voxels of the dyad
};

// The spanning tree of one dyad, in transform-array coordinates (what Eq. 1-3 of III-F use).
struct DyadTree {
  int level = 0;
  int subband = kDiagonalSubband;
  CoefficientBlock block;                 // where the dyad lies in the array
  std::vector<std::array<int, 3>> cells;  // absolute array indices of the nodes
  std::vector<double> coefficients;       // their coefficient values
  std::vector<std::uint32_t> parent;      // kNoParent for the root
  std::vector<std::uint32_t> leaves;      // leaves in each node's subtree (Da Vinci weight)
  std::uint32_t root = kNoParent;         // kNoParent when the dyad has no significant node
  double length = 0.0;                    // total edge length, in dyad voxels

  std::size_t size() const { return cells.size(); }
};

// The MST of dyad `level` (III-E). Throws std::out_of_range for a level outside the pyramid.
DyadTree dyad_tree(const WaveletPyramid& pyramid, int level, const DyadTreeOptions& options = {});

// One tree per dyad, levels 0 .. L-1.
std::vector<DyadTree> dyad_trees(const WaveletPyramid& pyramid,
                                 const DyadTreeOptions& options = {});

// The tree as a Skeleton: node positions are the centres of the regions the dyad's cells cover in
// the transformed grid's frame (origin, voxel_size of pyramid.coefficients), mapped to world
// coordinates when `alignment` is given. Nodes are in breadth-first order from the root (parents
// before children); branch order follows the child with most leaves as the continuation.
Skeleton to_skeleton(const DyadTree& tree, const WaveletPyramid& pyramid,
                     const DyadTreeOptions& options = {}, const Alignment* alignment = nullptr);

}  // namespace ramus::wavelet
