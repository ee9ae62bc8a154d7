// The 3D Haar wavelet transform of a voxel grid (Friedman & Stamos 2013, III-B), in the standard
// and the nonstandard decomposition of Stollnitz, DeRose & Salesin, "Wavelets for computer
// graphics: a primer, part 1" (1995), section 3.
//
// Normalization: the primer's *averaging and differencing* Haar, as the paper uses it:
//   forward  a = (x0 + x1) / 2,  d = (x0 - x1) / 2;   inverse  x0 = a + d,  x1 = a - d.
// With voxel values in [0, 1] every coefficient stays in [-1, 1], the scaling coefficient is the
// mean value and a detail is at most its cell's mean in magnitude, which is the scale the paper's
// fixed thresholds (0.2 for compression, 0.3 for the spanning trees) are read in. The orthonormal
// Haar (PyWavelets, "haar") differs by a factor 2^(m/2) per axis, m being the number of 1D steps
// that produced the coefficient along that axis; `orthonormal_scale` gives the factor.
//
// Layout (both decompositions), side n = 2^L, index x + n*(y + n*z) as in VoxelGrid:
// along an axis of the *standard* transform, index 0 holds the scaling coefficient and indices
// [2^j, 2^(j+1)) the details of level j (j = 0 coarsest, L-1 finest). The *nonstandard*
// transform stores level j's seven detail subbands in the cubes whose corner along axis k is
// 2^j when the subband differences along k, else 0 (subband s = bit 0 x, bit 1 y, bit 2 z), and the
// scaling coefficient at (0, 0, 0). In both, the diagonal cube [2^j, 2^(j+1))^3 is "dyad j"
// (details along all three axes at level j); it holds the same numbers in the two decompositions.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "compiler/voxel_rule.h"  // kDiagonalSubband: details along x, y and z
#include "infer/wavelet/voxel_grid.h"

namespace ramus::wavelet {

enum class Decomposition { standard, nonstandard };

// An axis-aligned box of coefficients inside the pyramid's array.
struct CoefficientBlock {
  std::array<std::size_t, 3> offset{0, 0, 0};
  std::array<std::size_t, 3> size{1, 1, 1};
  std::size_t count() const { return size[0] * size[1] * size[2]; }
};

struct WaveletPyramid {
  Decomposition decomposition = Decomposition::standard;
  // Coefficients in the layout above; origin and voxel_size are the transformed grid's.
  VoxelGrid coefficients;

  int levels() const { return coefficients.levels; }
  double scaling() const { return coefficients.values[0]; }
  // Dyad j in [0, levels): the diagonal cube [2^j, 2^(j+1))^3.
  CoefficientBlock dyad(int j) const;
  // Nonstandard subband s in [1, 7] of level j (also valid for a standard pyramid's diagonal, s=7).
  CoefficientBlock subband(int j, int s) const;
  // Standard block with levels (jx, jy, jz) per axis; -1 selects the scaling index 0 on that axis.
  CoefficientBlock standard_block(int jx, int jy, int jz) const;
  double at(const CoefficientBlock& b, std::size_t i, std::size_t j, std::size_t k) const {
    return coefficients.at(b.offset[0] + i, b.offset[1] + j, b.offset[2] + k);
  }
};

// Forward transform of a grid (III-B). Runs in O(n^3) with TBB over lines/planes.
WaveletPyramid haar_forward(const VoxelGrid& grid, Decomposition decomposition);
// Inverse transform: haar_inverse(haar_forward(g, d)) equals g to rounding (|error| < 1e-12
// for values in [0, 1]).
VoxelGrid haar_inverse(const WaveletPyramid& pyramid);

// One synthesis step of the nonstandard transform on the cube [0, 2m)^3 of `coefficients`
// (approximation in [0, m)^3, seven subbands around it). Used by the super-resolution of III-D,
// which appends a level above a grid.
void haar_inverse_step_nonstandard(VoxelGrid& coefficients, std::size_t m);

// The averaging-Haar approximations of every level: result[j] has side 2^j and holds the mean of
// the grid over each cell (result[levels] is the grid itself). Detail cell i of level j describes
// the 2x2x2 block of result[j + 1] whose mean is result[j] at i.
std::vector<VoxelGrid> approximation_levels(const VoxelGrid& grid);

// Factor f with orthonormal_coefficient = f * averaging_coefficient at array index (x, y, z).
double orthonormal_scale(Decomposition decomposition, int levels, std::size_t x, std::size_t y,
                         std::size_t z);

}  // namespace ramus::wavelet
