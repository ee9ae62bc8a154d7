// Inflating BSGs (Livny et al. 2010, section 4.3): radii from Eq. 6 + 7, and the clustering of
// edges whose generalized cylinders overlap (edge removal and degree-2 collapse).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "reconstruct/bsg/bsg.h"

namespace ramus::bsg {

struct InflateParams {
  double exponent = 2.5;   // allometric exponent of Eq. 5
  double overlap = 0.5;    // collapse when more than this fraction of a cylinder is covered
  double own_weight = 0;   // per-vertex weight added to subtree lengths (see importance_weights)
  double edge_sample = 0;  // spacing of samples along edges when measuring d_avg
  double min_radius = 0;   // cylinders are at least this thick in the overlap tests
  double min_twig = 0;     // twigs shorter than this are pruned after clustering
  double root_radius = 0;  // measured trunk radius at the base (0: unknown, use d_avg alone)
  double tolerance = 0;    // shape tolerance of degree-2 collapses (at least the radius)
};

// Radii minimizing Eq. 6 + Eq. 7 for the given d_avg. See the .cpp for why this is exact.
// With root_radius > 0 the free scale is fixed by the measured trunk instead of Eq. 7.
void assign_radii(Bsg& bsg, double d_avg, double exponent, double root_radius = 0);

// One sweep of edge removal and degree-2 collapse; returns the number of edges collapsed.
// Cylinders thinner than min_radius are widened to it for the overlap test. A degree-2 collapse
// must keep both removed positions within max(radius, tolerance) of the new polyline, and with
// `absorbed` (one list per vertex, kept from call to call; inflate() passes one) every position
// the two took in by earlier degree-2 collapses as well.
std::size_t collapse_overlaps(Bsg& bsg, double overlap, double min_radius, double tolerance = 0,
                              std::vector<std::vector<Eigen::Vector3d>>* absorbed = nullptr);

// Removes twigs (leaf chains from a fork) shorter than min_length: scan noise that survived
// the clustering. Returns the number of vertices removed.
std::size_t prune_twigs(Bsg& bsg, double min_length);

// Alternates weights -> d_avg -> radii -> collapse until no edge collapses. Returns rounds run.
int inflate(Bsg& bsg, const std::vector<Eigen::Vector3d>& samples,
            const std::vector<std::uint32_t>& counts, const InflateParams& params);

}  // namespace ramus::bsg
