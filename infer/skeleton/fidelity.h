// Fidelity statistics of inferred grammars: distributions measured on skeletons and the
// two-sample Kolmogorov-Smirnov distance between them (`ramus compare`).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/skeleton.h"

namespace ramus::skeleton_infer {

// Exact two-sample Kolmogorov-Smirnov statistic D = sup_x |F_a(x) - F_b(x)| of the empirical
// distribution functions (ties handled: both functions step past a shared value together).
// 0 when both samples are empty, 1 when exactly one is.
double ks_distance(std::vector<double> a, std::vector<double> b);

enum class Measure {
  BranchLength,    // internode path length
  BranchingAngle,  // theta of every child at a branch node (degrees)
  Azimuth,         // phi of every child (degrees)
  RadiusRatio,     // b of every child
  BranchOrder,     // order of every internode
  TotalLength,     // per tree: sum of segment lengths
  CrownExtent,     // per tree: largest horizontal extent of its nodes
  Height,          // per tree: vertical extent of its nodes
};
inline constexpr std::size_t kMeasureCount = 8;
const char* measure_name(Measure m);

// The samples of every measure, pooled over any number of trees.
struct Distributions {
  std::array<std::vector<double>, kMeasureCount> samples;
  std::size_t trees = 0;
  std::vector<double>& operator[](Measure m) { return samples[std::size_t(m)]; }
  const std::vector<double>& operator[](Measure m) const { return samples[std::size_t(m)]; }
};

// Measures are recorded to kMeasureDigits significant digits (to_resolution), the precision of
// the numbers an inferred grammar writes. Exact, a grammar-grown input's repeated values (a
// weeping tree's whips are all 3.6 m long, summed from 12 internodes of 0.3) and the regrown
// ones (3.6 written, or exp(1.281) = 3.6004) would differ in their last bits, and the KS
// distance would be the whole mass of the repeat (0.6 for those whips) for a difference of one
// part in 10^4 -- far below a scan's resolution.
inline constexpr int kMeasureDigits = 4;
double to_resolution(double v);

// Adds the samples of every tree (root with at least one segment) of `skeleton` to `into`.
// Throws ExtractError for an invalid skeleton.
void measure(const Skeleton& skeleton, Distributions& into);

struct MeasureComparison {
  Measure measure;
  std::size_t count_a = 0, count_b = 0;
  double mean_a = 0, mean_b = 0;
  double ks = 0;
};

std::vector<MeasureComparison> compare(const Distributions& a, const Distributions& b);

}  // namespace ramus::skeleton_infer
