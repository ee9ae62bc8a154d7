// Quantizing wavelet coefficients to the K classes of a voxel grammar (III-C).
//
// The paper maps "a voxel in one dyad to the eight voxels in the subsequent dyad" and picks among
// rules "for a given voxel value", so values must be discrete. We use a *mid-tread uniform*
// quantizer, symmetric about zero: with K = 2h + 1 classes and range R,
//   step  = R / h,   class(c) = h + clamp(round(c / step), -h, h),   value(k) = (k - h) * step.
// Class h is exactly zero, so the empty space and the solid interior (all-zero details) keep their
// own class and a zero coefficient reconstructs to exactly zero. R is the largest magnitude among
// the values being quantized (voxel_grammar.h quantizes each detail divided by its cell's mean,
// which lies in [-1, 1]); with occupancy grids the finest such values are multiples of 1/8 (one
// voxel of eight), which K = 17 and R = 1 represent exactly.
#pragma once

#include <cstdint>

namespace ramus::wavelet {

inline constexpr int kDefaultClasses = 17;
inline constexpr int kMaxClasses = 255;  // classes are stored as bytes

struct CoefficientQuantizer {
  int classes = kDefaultClasses;  // K, odd, in [3, kMaxClasses]
  double range = 0.5;             // R > 0

  int half() const { return (classes - 1) / 2; }
  int zero_class() const { return half(); }
  double step() const { return range / half(); }
  std::uint8_t quantize(double c) const;
  double value(int cls) const { return (cls - half()) * step(); }
};

// A quantizer with `classes` classes and range `range` (1 when range is not > 0). Throws
// std::invalid_argument for an even or out-of-range class count.
CoefficientQuantizer make_quantizer(double range, int classes = kDefaultClasses);

}  // namespace ramus::wavelet
