#include "cli/compare_distance.h"

#include <algorithm>
#include <cstdio>

#include "reconstruct/bsg/compare.h"

namespace ramus::cli {

DistanceReport measure_distances(const CompareSide& a, const CompareSide& b,
                                 const std::vector<double>& within) {
  DistanceReport report;
  if (within.empty()) return report;
  report.step = 0.2 * *std::min_element(within.begin(), within.end());
  CompareOptions o;
  o.spacing = report.step;
  o.distances = within;
  const SkeletonComparison c = compare_skeletons(a.trees, b.trees, o);
  for (std::size_t k = 0; k < within.size(); ++k)
    report.rows.push_back({within[k], c.precision_within[k], c.recall_within[k]});
  report.length_a = c.length_truth, report.length_b = c.length_reconstructed;
  report.tips_a = c.branches_truth, report.tips_b = c.branches_reconstructed;
  return report;
}

void print_distance_report(const DistanceReport& report) {
  std::printf("skeleton B against reference A (sampled every %g):\n", report.step);
  std::printf("%-12s %10s %10s\n", "within", "precision", "recall");
  for (const DistanceRow& r : report.rows)
    std::printf("%-12g %10.4f %10.4f\n", r.within, r.precision, r.recall);
  std::printf("length: A %.4g, B %.4g (B / A %.4f); tips: A %zu, B %zu\n", report.length_a,
              report.length_b, report.length_a > 0 ? report.length_b / report.length_a : 0.0,
              report.tips_a, report.tips_b);
}

}  // namespace ramus::cli
