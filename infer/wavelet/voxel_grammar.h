// The voxel grammar of Friedman & Stamos 2013, III-C.
//
// "We construct a voxel grammar by mapping a voxel in one dyad to the eight voxels in the
// subsequent dyad. We iterate across each level of detail generating rules that map voxels from
// coarse details to finer ones. [...] If we have many rules for a given voxel value we choose one
// of the applicable rules stochastically."
//
// A rule is (subband, parent class) -> 8 child classes, weighted by how often it was observed.
// The coefficient at local position (i, j, k) of a subband at level l is the parent of the eight
// coefficients (2i + dx, 2j + dy, 2k + dz) of the same subband at level l + 1; child c is
// (dx, dy, dz) = (c & 1, c >> 1 & 1, c >> 2 & 1). For a nonstandard pyramid every one of the seven
// subbands (haar.h) forms its own chain of dyads; for a standard pyramid only the diagonal dyads
// (subband 7) nest this way. Rules from all levels are pooled: the paper's premise is that the
// tree is self-similar across scales. The table {subband, parent, children, count} is what a
// `voxels` block spells as `parent -> [c0 .. c7] x count`.
//
// What is quantized (the paper says only "voxel value"): by default (`relative`) each detail
// divided by the mean of its cell (the approximation of the same level and position, see
// approximation_levels), a contrast in [-1, 1] that is 0 where the cell is empty. Raw
// averaging-Haar details of a sparse structure shrink by the occupied fraction at every coarser
// level, so rules learned from raw values never match the finest level they are applied to;
// contrasts of an exactly self-similar shape are the same at every level, and a synthesized
// contrast is turned back into a detail by multiplying with the (known) mean of the finer cell.
// `relative = false` quantizes the raw coefficients, the literal reading.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "compiler/voxel_rule.h"
#include "core/rng.h"
#include "infer/wavelet/haar.h"
#include "infer/wavelet/quantizer.h"

namespace ramus::wavelet {

struct VoxelGrammarOptions {
  int classes = kDefaultClasses;
  int first_level = 0;   // parents are taken from levels [first_level, L - 2]
  bool relative = true;  // quantize detail / cell mean (see above) instead of the raw detail
};

struct VoxelGrammar {
  CoefficientQuantizer quantizer;
  Decomposition decomposition = Decomposition::nonstandard;
  int levels = 0;  // of the grid the rules were learned from
  bool relative = true;
  // Sorted by (subband, parent), then by decreasing count, then by children: deterministic.
  std::vector<VoxelRule> rules;
  // Rules that apply to (subband, parent): [first, last) into `rules`. When that parent class was
  // never observed in the subband, the rules of the nearest observed class (ties: the smaller);
  // an empty range when the subband has no rules. Needs build_index() after `rules` changed.
  std::pair<std::uint32_t, std::uint32_t> rules_for(int subband, int parent) const;
  // Sorts `rules` into the order above and rebuilds the lookup table.
  void build_index();
  std::uint64_t observations() const;

 private:
  std::vector<std::pair<std::uint32_t, std::uint32_t>> index_;  // [subband * classes + parent]
};

// Learns the rules from every pair of consecutive dyads of the pyramid (III-C). `approximations`
// is approximation_levels() of the transformed grid (computed when omitted). Throws
// std::invalid_argument for bad options.
VoxelGrammar learn_voxel_grammar(const WaveletPyramid& pyramid,
                                 const std::vector<VoxelGrid>& approximations,
                                 const VoxelGrammarOptions& options = {});
VoxelGrammar learn_voxel_grammar(const WaveletPyramid& pyramid,
                                 const VoxelGrammarOptions& options = {});

// The value the grammar quantizes for coefficient (i, j, k) of `block` at `level`.
double grammar_value(const VoxelGrammar& grammar, const WaveletPyramid& pyramid,
                     const std::vector<VoxelGrid>& approximations, int level,
                     const CoefficientBlock& block, std::size_t i, std::size_t j, std::size_t k);

// Draws one of rules_for(subband, parent) with probability count / total; nullptr when none.
const VoxelRule* pick_rule(const VoxelGrammar& grammar, int subband, int parent, Rng& rng);

// Applies the grammar to subband `subband` of `level` of the pyramid and returns the synthesized
// values of the next level (side 2^(level+1), x fastest), dequantized but still in the grammar's
// normalization (contrasts when `relative`: multiply by the finer cell's mean). Each parent draws
// from its own stream Rng::stream(seed, subband, parent index): the result depends only on the
// seed.
std::vector<double> synthesize_subband(const VoxelGrammar& grammar, const WaveletPyramid& pyramid,
                                       const std::vector<VoxelGrid>& approximations, int level,
                                       int subband, std::uint64_t seed);

}  // namespace ramus::wavelet
