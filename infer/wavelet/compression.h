// Wavelet compression figures (Friedman & Stamos 2013, IV-A and Table I).
//
// "The lossless compression ratio is calculated as the number of wavelet coefficients equal to
// zero out of the total number of coefficients. The lossy compression rate is the number of
// wavelet coefficients below a threshold gamma" (gamma = 0.2). Both count every coefficient of the
// array, the scaling coefficient included, and "below" compares magnitudes |c| < gamma. With
// averaging-Haar coefficients of occupancy values (dyadic rationals) the zero test is exact.
//
// Which coefficient values gamma is compared with: the paper cites the primer of Stollnitz et al.,
// whose compression (part 1, section 2.4) thresholds the *normalized* (orthonormal) coefficients,
// so that dropping them costs at most their L2 energy. That is the default here; the averaging
// values of haar.h shrink with the occupied fraction at coarse levels and would drop nearly all
// of a sparse tree (lossy IoU near 0), contradicting the paper's "without introducing many
// artifacts". The lossless figure is the same for both (zero is zero).
//
// The reconstruction error of the lossy version is measured as voxel IoU: the coefficients below
// gamma are set to zero, the grid is inverse-transformed, and the voxels whose reconstructed value
// exceeds half the smallest non-zero input value (0.5 for occupancy) are compared with the input's
// non-zero voxels.
#pragma once

#include <cstddef>

#include "infer/wavelet/haar.h"

namespace ramus::wavelet {

enum class CoefficientScale { orthonormal, averaging };

struct CompressionStats {
  std::size_t coefficients = 0;
  std::size_t zeros = 0;         // exactly zero
  std::size_t below_gamma = 0;   // |c| < gamma
  double lossless_ratio = 0.0;   // zeros / coefficients
  double lossy_ratio = 0.0;      // below_gamma / coefficients
  double lossy_iou = 1.0;        // voxel IoU of the gamma-thresholded reconstruction vs the input
  std::size_t input_voxels = 0;  // non-zero input voxels
};

// Sets every coefficient with |c| < gamma (c read in `scale`) to zero, in place; returns how many.
std::size_t threshold_coefficients(WaveletPyramid& pyramid, double gamma,
                                   CoefficientScale scale = CoefficientScale::orthonormal);

// `grid` is the transformed input; `pyramid` its forward transform (either decomposition).
CompressionStats compression_stats(const VoxelGrid& grid, const WaveletPyramid& pyramid,
                                   double gamma = 0.2,
                                   CoefficientScale scale = CoefficientScale::orthonormal);

}  // namespace ramus::wavelet
