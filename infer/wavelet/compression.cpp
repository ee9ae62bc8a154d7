#include "infer/wavelet/compression.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace ramus::wavelet {

namespace {

// Calls f(index, value in `scale`) for every coefficient. The orthonormal factors come from
// orthonormal_scale(), tabulated per axis index (standard) or per level (nonstandard).
template <class F>
void for_each_scaled(const WaveletPyramid& p, CoefficientScale scale, F&& f) {
  const VoxelGrid& g = p.coefficients;
  const bool ortho = scale == CoefficientScale::orthonormal;
  const bool standard = p.decomposition == Decomposition::standard;
  std::vector<double> axis(g.n, 1.0), level(std::size_t(p.levels()) + 1, 1.0);
  for (std::size_t i = 0; i < g.n; ++i) {
    axis[i] = std::cbrt(orthonormal_scale(Decomposition::standard, p.levels(), i, i, i));
  }
  for (int j = 0; j <= p.levels(); ++j) {
    std::size_t i = j == 0 ? 0 : std::size_t(1) << (j - 1);
    level[std::size_t(j)] = orthonormal_scale(Decomposition::nonstandard, p.levels(), i, i, i);
  }
  for (std::size_t z = 0; z < g.n; ++z) {
    for (std::size_t y = 0; y < g.n; ++y) {
      for (std::size_t x = 0; x < g.n; ++x) {
        double c = g.at(x, y, z);
        if (ortho && c != 0.0) {
          c *= standard ? axis[x] * axis[y] * axis[z]
                        : level[std::size_t(std::bit_width(std::max({x, y, z})))];
        }
        f(g.index(x, y, z), c);
      }
    }
  }
}

}  // namespace

std::size_t threshold_coefficients(WaveletPyramid& pyramid, double gamma, CoefficientScale scale) {
  std::size_t dropped = 0;
  std::vector<double>& v = pyramid.coefficients.values;
  // Writing zeros only lowers |c|, so thresholding while reading stays correct.
  for_each_scaled(pyramid, scale, [&](std::size_t i, double c) {
    if (std::abs(c) < gamma) {
      dropped += 1;
      v[i] = 0.0;
    }
  });
  return dropped;
}

CompressionStats compression_stats(const VoxelGrid& grid, const WaveletPyramid& pyramid,
                                   double gamma, CoefficientScale scale) {
  if (!(gamma >= 0) || !std::isfinite(gamma)) {
    throw std::invalid_argument("gamma must be a finite number >= 0");
  }
  if (grid.n != pyramid.coefficients.n) {
    throw std::invalid_argument("compression_stats: grid and pyramid differ in size");
  }
  CompressionStats s;
  s.coefficients = pyramid.coefficients.size();
  for_each_scaled(pyramid, scale, [&](std::size_t, double c) {
    s.zeros += c == 0.0;
    s.below_gamma += std::abs(c) < gamma;
  });
  s.lossless_ratio = double(s.zeros) / double(s.coefficients);
  s.lossy_ratio = double(s.below_gamma) / double(s.coefficients);

  double smallest = std::numeric_limits<double>::max();
  for (double v : grid.values) {
    if (v > 0) {
      smallest = std::min(smallest, v);
      s.input_voxels += 1;
    }
  }
  if (s.input_voxels == 0) return s;  // nothing to reconstruct: IoU 1 by convention
  WaveletPyramid lossy = pyramid;
  threshold_coefficients(lossy, gamma, scale);
  VoxelGrid rec = haar_inverse(lossy);
  s.lossy_iou = voxel_iou(grid, 0.0, rec, smallest / 2);
  return s;
}

}  // namespace ramus::wavelet
