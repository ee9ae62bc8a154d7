// Comparing a reconstructed skeleton with a known one (the accuracy harness of the simulated
// scans): both are sampled densely along their segments and matched by nearest samples.
#pragma once

#include <vector>

#include "core/skeleton.h"

namespace ramus {

struct CompareOptions {
  double radius_factor = 2.0;  // a sample matches when within radius_factor x the truth radius
  double distance = 0.1;       // ... or, for the fixed-distance scores, within this distance
  double spacing = 0.02;       // sampling step along segments
  double min_radius = 0.0;     // floor under truth radii (thin twigs), in the cloud's units
};

struct SkeletonComparison {
  double precision = 0;           // reconstructed samples within t x radius of the truth
  double recall = 0;              // truth samples within t x radius of the reconstruction
  double precision_distance = 0;  // the same within the fixed distance
  double recall_distance = 0;
  double chamfer = 0;             // mean of the two mean nearest-sample distances
  double length_truth = 0, length_reconstructed = 0;
  double length_ratio = 0;        // reconstructed / truth
  std::size_t branches_truth = 0, branches_reconstructed = 0;  // branch tips
};

SkeletonComparison compare_skeletons(const std::vector<Skeleton>& truth,
                                     const std::vector<Skeleton>& reconstructed,
                                     const CompareOptions& options);

}  // namespace ramus
