// Comparing a reconstructed skeleton with a known one (the accuracy harness of the simulated
// scans): both are sampled densely along their segments and matched by nearest samples.
#pragma once

#include <vector>

#include "core/point_cloud.h"
#include "core/skeleton.h"

namespace ramus {

struct CompareOptions {
  double radius_factor = 2.0;  // a sample matches when within radius_factor x the truth radius
  double distance = 0.1;       // ... or, for the fixed-distance scores, within this distance
  // Further fixed distances, scored in the same matching pass as `distance`
  // (SkeletonComparison::precision_within, recall_within).
  std::vector<double> distances;
  double spacing = 0.02;       // sampling step along segments
  double min_radius = 0.0;     // floor under truth radii (thin twigs), in the cloud's units
  // Bounds of the radius classes of the centre-line error (truth radii, unfloored), ascending:
  // {0.05, 0.1, 0.2, 0.4, 0.65} gives the classes [5, 10), [10, 20), [20, 40), [40, 65) cm.
  std::vector<double> radius_classes;
  // The scan the reconstruction came from (in the truth's coordinates, offset applied), or
  // null. With it, every truth sample is also marked seen or not, and the scores are also given
  // over the seen wood: a truth sample is seen when scan points on its bark (within
  // bark_band x its radius + bark_floor of the surface, in a slab of max(radius / 4, spacing)
  // either side across the segment) cover at least seen_arc radians of its circumference. A
  // circle's centre is not fixed by less (one_sided_sections.h fits arcs from 60 degrees); a
  // branch hidden behind others from one station has no points at all. What is not seen no
  // method can place but by guessing, so the scores over the seen wood say how well the
  // reconstruction uses the points it has, and the seen share how much a scan allows.
  const PointCloud* scan = nullptr;
  double seen_arc = 60.0 * 3.14159265358979323846 / 180;
  double bark_band = 0.3;
  double bark_floor = 0.01;
  // Keep every truth sample of the radius classes with its centre-line error
  // (SkeletonComparison::centre_samples): where the errors are, for drawing them.
  bool keep_samples = false;
};

// One truth sample of a radius class: where it is, its segment's direction, its radius
// (unfloored), the distance to the nearest reconstructed segment divided by that radius, and
// whether the scan saw it.
struct CentreSample {
  Vec3 position, direction;
  double radius = 0, error = 0;
  bool seen = false;
};

// Centre-line error of one class of truth radii: the distance from each truth sample to the
// nearest reconstructed segment, divided by the truth radius there.
struct CentreError {
  double lo = 0, hi = 0;       // truth radii in [lo, hi)
  std::size_t samples = 0;     // truth samples in the class
  double median = 0, p90 = 0;  // of distance / radius
  // The median over the samples the reconstruction found (within 2 x radius): how well the
  // found branches are centred, apart from the branches missed (which recall counts).
  double median_found = 0;
  std::size_t seen = 0;    // samples seen by the scan (CompareOptions::scan; 0 without it)
  double median_seen = 0;  // the median over those
};

struct SkeletonComparison {
  double precision = 0;           // reconstructed samples within t x radius of the truth
  double recall = 0;              // truth samples within t x radius of the reconstruction
  double precision_1r = 0;        // the same within 1 x radius (the uc-vision synthetic-trees
  double recall_1r = 0;           // evaluation reports 1x and 2x)
  double precision_distance = 0;  // the same within the fixed distance
  double recall_distance = 0;
  // Per CompareOptions::distances, in its order: the shares within each.
  std::vector<double> precision_within, recall_within;
  double chamfer = 0;  // mean of the two mean nearest-sample distances
  double length_truth = 0, length_reconstructed = 0;
  double length_ratio = 0;                                     // reconstructed / truth
  std::size_t branches_truth = 0, branches_reconstructed = 0;  // branch tips
  std::vector<CentreError> centre_error;  // one per radius class (CompareOptions)
  double centre_error_median = 0;         // over all classes' samples (0 when no class)
  // With CompareOptions::scan: the share of the truth's samples the scan saw, the recall (within
  // radius_factor x radius) over those, and the centre-line error's median over the seen
  // samples of all classes.
  double seen_fraction = 0, recall_seen = 0, centre_error_median_seen = 0;
  // With CompareOptions::keep_samples: the samples behind centre_error, in the truth's order.
  std::vector<CentreSample> centre_samples;
};

SkeletonComparison compare_skeletons(const std::vector<Skeleton>& truth,
                                     const std::vector<Skeleton>& reconstructed,
                                     const CompareOptions& options);

}  // namespace ramus
