// Compression figures of IV-A / Table I (infer/wavelet/compression.h).
#include <catch2/catch.hpp>

#include "infer/wavelet/compression.h"
#include "wavelet_test_util.h"

using namespace ramus::wavelet;

TEST_CASE("compression: a constant grid compresses to its scaling coefficient", "[wavelet]") {
  VoxelGrid g(3);
  for (double& v : g.values) v = 1;
  CompressionStats s = compression_stats(g, haar_forward(g, Decomposition::standard));
  CHECK(s.coefficients == 512);
  CHECK(s.zeros == 511);
  CHECK(s.below_gamma == 511);
  CHECK(s.lossless_ratio == Approx(511.0 / 512));
  CHECK(s.lossy_iou == 1.0);
  CHECK(s.input_voxels == 512);
}

TEST_CASE("compression: counts on a single voxel by hand", "[wavelet]") {
  VoxelGrid g(2);
  g.at(1, 2, 3) = 1;
  // Nonstandard: level 1 details of the one non-empty 2x2x2 block are +-1/8 (7 of them), level 0
  // details and the scaling coefficient are +-1/64: 15 non-zero coefficients of 64.
  WaveletPyramid p = haar_forward(g, Decomposition::nonstandard);
  CompressionStats s = compression_stats(g, p, 0.2, CoefficientScale::averaging);
  CHECK(s.zeros == 64 - 15);
  CHECK(s.below_gamma == 64);  // every averaging coefficient is below 0.2
  CHECK(s.lossy_iou == 0.0);   // ...so the lossy version loses the voxel
  // Orthonormal: the finest details are 1/8 * 2^(3/2) = 0.354 and survive, the coarse ones
  // (1/64 * 2^3 = 0.125) do not; the seven finest details alone rebuild the voxel (7/8 > 1/2).
  CompressionStats o = compression_stats(g, p, 0.2);
  CHECK(o.zeros == s.zeros);
  CHECK(o.below_gamma == 64 - 7);
  CHECK(o.lossy_iou == 1.0);
  CompressionStats exact = compression_stats(g, p, 0.0);
  CHECK(exact.below_gamma == 0);
  CHECK(exact.lossy_iou == 1.0);
}

TEST_CASE("compression: lossy share grows with gamma and the IoU falls", "[wavelet]") {
  VoxelGrid g = test::random_grid(5, 3, 0.05);
  WaveletPyramid p = haar_forward(g, Decomposition::standard);
  CompressionStats lo = compression_stats(g, p, 0.01), hi = compression_stats(g, p, 0.3);
  CHECK(lo.lossy_ratio < hi.lossy_ratio);
  CHECK(lo.lossless_ratio == hi.lossless_ratio);
  CHECK(lo.lossy_iou >= hi.lossy_iou);
  CHECK(lo.lossless_ratio <= lo.lossy_ratio);
  WaveletPyramid t = p;
  CHECK(threshold_coefficients(t, 0.3) == hi.below_gamma);
  std::size_t nonzero = 0;
  for (double c : t.coefficients.values) nonzero += c != 0;
  CHECK(nonzero == t.coefficients.size() - hi.below_gamma);
  CHECK_THROWS_AS(compression_stats(g, p, -1), std::invalid_argument);
}
