// Haar transform kernels. A 1D step along x works on contiguous lines; along y and z it works on
// whole x-runs at once (rows of a plane), so that strided axes still stream through memory.
#include "infer/wavelet/haar.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace ramus::wavelet {
namespace {

using Extent = std::array<std::size_t, 3>;

// One analysis (forward) or synthesis (inverse) step along x on the box [0, ext).
void step_x(std::vector<double>& v, std::size_t n, const Extent& ext, bool inverse) {
  const std::size_t m = ext[0], h = m / 2;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ext[2]), [&](const auto& r) {
    std::vector<double> tmp(m);
    for (std::size_t z = r.begin(); z < r.end(); ++z) {
      for (std::size_t y = 0; y < ext[1]; ++y) {
        double* line = v.data() + n * (y + n * z);
        for (std::size_t i = 0; i < h; ++i) {
          if (inverse) {
            tmp[2 * i] = line[i] + line[h + i];
            tmp[2 * i + 1] = line[i] - line[h + i];
          } else {
            tmp[i] = (line[2 * i] + line[2 * i + 1]) / 2;
            tmp[h + i] = (line[2 * i] - line[2 * i + 1]) / 2;
          }
        }
        std::copy(tmp.begin(), tmp.end(), line);
      }
    }
  });
}

// One step along y (axis 1) or z (axis 2): rows of length ext[0] along x are combined pairwise.
void step_yz(std::vector<double>& v, std::size_t n, int axis, const Extent& ext, bool inverse) {
  const std::size_t m = ext[axis], h = m / 2, ex = ext[0];
  const std::size_t stride = axis == 1 ? n : n * n;
  const int other = axis == 1 ? 2 : 1;
  const std::size_t other_stride = other == 1 ? n : n * n;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ext[other]), [&](const auto& r) {
    std::vector<double> tmp(m * ex);
    for (std::size_t t = r.begin(); t < r.end(); ++t) {
      double* base = v.data() + t * other_stride;
      for (std::size_t i = 0; i < h; ++i) {
        if (inverse) {
          const double* a = base + i * stride;
          const double* d = base + (h + i) * stride;
          double* o0 = tmp.data() + 2 * i * ex;
          double* o1 = o0 + ex;
          for (std::size_t x = 0; x < ex; ++x) {
            o0[x] = a[x] + d[x];
            o1[x] = a[x] - d[x];
          }
        } else {
          const double* r0 = base + 2 * i * stride;
          const double* r1 = r0 + stride;
          double* a = tmp.data() + i * ex;
          double* d = tmp.data() + (h + i) * ex;
          for (std::size_t x = 0; x < ex; ++x) {
            a[x] = (r0[x] + r1[x]) / 2;
            d[x] = (r0[x] - r1[x]) / 2;
          }
        }
      }
      for (std::size_t i = 0; i < m; ++i) {
        std::copy(tmp.data() + i * ex, tmp.data() + (i + 1) * ex, base + i * stride);
      }
    }
  });
}

void step(std::vector<double>& v, std::size_t n, int axis, const Extent& ext, bool inverse) {
  if (axis == 0) {
    step_x(v, n, ext, inverse);
  } else {
    step_yz(v, n, axis, ext, inverse);
  }
}

// Level of an index along one axis of the standard layout: -1 for the scaling index 0.
int index_level(std::size_t i) { return i == 0 ? -1 : int(std::bit_width(i)) - 1; }

}  // namespace

CoefficientBlock WaveletPyramid::dyad(int j) const { return subband(j, kDiagonalSubband); }

CoefficientBlock WaveletPyramid::subband(int j, int s) const {
  if (j < 0 || j >= levels() || s < 1 || s > 7) {
    throw std::out_of_range("no subband " + std::to_string(s) + " at level " + std::to_string(j));
  }
  CoefficientBlock b;
  std::size_t side = std::size_t(1) << j;
  for (int k = 0; k < 3; ++k) {
    b.offset[k] = (s >> k) & 1 ? side : 0;
    b.size[k] = side;
  }
  return b;
}

CoefficientBlock WaveletPyramid::standard_block(int jx, int jy, int jz) const {
  CoefficientBlock b;
  const int js[3] = {jx, jy, jz};
  for (int k = 0; k < 3; ++k) {
    if (js[k] < -1 || js[k] >= levels()) {
      throw std::out_of_range("no standard block at level " + std::to_string(js[k]));
    }
    b.offset[k] = js[k] < 0 ? 0 : std::size_t(1) << js[k];
    b.size[k] = js[k] < 0 ? 1 : std::size_t(1) << js[k];
  }
  return b;
}

WaveletPyramid haar_forward(const VoxelGrid& grid, Decomposition decomposition) {
  WaveletPyramid p;
  p.decomposition = decomposition;
  p.coefficients = grid;
  std::vector<double>& v = p.coefficients.values;
  const std::size_t n = grid.n;
  if (decomposition == Decomposition::standard) {
    // Full 1D decomposition along each axis in turn (primer, section 3.1).
    for (int axis = 0; axis < 3; ++axis) {
      for (std::size_t m = n; m >= 2; m /= 2) {
        Extent ext{n, n, n};
        ext[axis] = m;
        step(v, n, axis, ext, false);
      }
    }
  } else {
    // One step along every axis per level, then recurse on the averages (primer, section 3.2).
    for (std::size_t m = n; m >= 2; m /= 2) {
      for (int axis = 0; axis < 3; ++axis) step(v, n, axis, {m, m, m}, false);
    }
  }
  return p;
}

void haar_inverse_step_nonstandard(VoxelGrid& coefficients, std::size_t m) {
  if (2 * m > coefficients.n || m == 0) {
    throw std::invalid_argument("inverse step of size " + std::to_string(m) +
                                " in a grid of side " + std::to_string(coefficients.n));
  }
  for (int axis = 2; axis >= 0; --axis) {
    step(coefficients.values, coefficients.n, axis, {2 * m, 2 * m, 2 * m}, true);
  }
}

VoxelGrid haar_inverse(const WaveletPyramid& pyramid) {
  VoxelGrid g = pyramid.coefficients;
  const std::size_t n = g.n;
  if (pyramid.decomposition == Decomposition::standard) {
    for (int axis = 2; axis >= 0; --axis) {
      for (std::size_t m = 2; m <= n; m *= 2) {
        Extent ext{n, n, n};
        ext[axis] = m;
        step(g.values, n, axis, ext, true);
      }
    }
  } else {
    for (std::size_t m = 1; 2 * m <= n; m *= 2) haar_inverse_step_nonstandard(g, m);
  }
  return g;
}

std::vector<VoxelGrid> approximation_levels(const VoxelGrid& grid) {
  std::vector<VoxelGrid> out(std::size_t(grid.levels) + 1);
  out[std::size_t(grid.levels)] = grid;
  for (int j = grid.levels - 1; j >= 0; --j) {
    const VoxelGrid& fine = out[std::size_t(j) + 1];
    VoxelGrid coarse(j);
    coarse.origin = grid.origin;
    coarse.voxel_size = fine.voxel_size * 2;
    for (std::size_t z = 0; z < fine.n; ++z) {
      for (std::size_t y = 0; y < fine.n; ++y) {
        for (std::size_t x = 0; x < fine.n; ++x) {
          coarse.at(x / 2, y / 2, z / 2) += fine.at(x, y, z) / 8;
        }
      }
    }
    out[std::size_t(j)] = std::move(coarse);
  }
  return out;
}

double orthonormal_scale(Decomposition decomposition, int levels, std::size_t x, std::size_t y,
                         std::size_t z) {
  // Each 1D step multiplies by 1/2 here and by 1/sqrt(2) in the orthonormal transform, so a
  // coefficient made by m steps along an axis is 2^(m/2) times larger in the orthonormal one.
  int steps = 0;
  if (decomposition == Decomposition::standard) {
    for (std::size_t i : {x, y, z}) steps += levels - std::max(index_level(i), 0);
  } else {
    steps = 3 * (levels - std::max(index_level(std::max({x, y, z})), 0));
  }
  return std::pow(2.0, 0.5 * steps);
}

}  // namespace ramus::wavelet
