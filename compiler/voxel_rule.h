// One rule of a voxel grammar: a coarse voxel's class -> the classes of its eight finer voxels
// (Friedman & Stamos 2013, III-C). It is the unit of the third kind of rule of the language
// (`voxels` blocks), stored by the .rmb codec (formats/rmb/) and learned from wavelet dyads by
// infer/wavelet/voxel_grammar.h, so it lives here, below both.
#pragma once

#include <array>
#include <cstdint>

namespace ramus::wavelet {

// The subband of details along x, y and z: the dyads proper. Subbands are numbered 1..7 by
// which axes carry a detail (infer/wavelet/haar.h).
inline constexpr int kDiagonalSubband = 7;

struct VoxelRule {
  std::uint8_t subband = kDiagonalSubband;  // 1..7
  std::uint8_t parent = 0;                  // class of the coarse coefficient
  std::array<std::uint8_t, 8> children{};   // classes of the eight finer coefficients
  std::uint32_t count = 0;                  // observations: the rule's weight
};

}  // namespace ramus::wavelet
