// Cross-sections seen from one side, fitted with a known radius. A scan from one station sees at
// most half of a branch, less where nearer branches hide it: the cross-sections of
// centre_line.h need 110 degrees of arc to fix a circle with a free radius, and on a 5-20 cm limb
// of thick_oak scanned from one station most unfitted slabs that hold points cover 60-110
// degrees (their free fits land a median 0.2-0.35 r off the axis, with radii within 10 % of the
// truth). With the radius known, an arc of 60 degrees fixes the centre: the circle of that radius
// through the arc lies on its concave side, one radius inward along the surface normal. The
// radius comes from the fits of the same branch (the nearest fitted nodes up and down the
// chain), as Livny et al. 2010 (4.3) carry radii along a branch from where they are measured
// and TreeQSM (Raumonen et al. 2013, 2.3) fits its cylinders along a segment; on a branch
// without any fit, from the median of the free circles of its chain's one-sided arcs (the
// radius of one short arc is noisy, of several it is not), at most its parent stem's.
// docs/reconstruction.md, "Centre lines", step 5.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "reconstruct/bsg/centre_line.h"
#include "reconstruct/bsg/kdtree.h"

namespace ramus::bsg {

struct KnownRadiusFit {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double residual = 0;         // robust scale of the inliers' distances to the circle
  double coverage = 0;         // arc (radians) the inliers cover
  double inlier_fraction = 0;  // weight share of the inliers (within 2.5 robust scales)
  bool valid = false;
};

// The circle of radius `r` that best fits `pts` (weights may be empty), started from `start`:
// Gauss-Newton on |p - c| - r over the centre, Huber then Tukey reweighted (circle_fit.h).
KnownRadiusFit fit_circle_known_radius(const std::vector<Eigen::Vector2d>& pts,
                                       const std::vector<double>& weights, double r,
                                       const Eigen::Vector2d& start, double noise,
                                       int iterations = 10);

// For every node neither a cross-section nor a chain cylinder placed (not a fork, radius hint
// at least CentreLineParams::min_hint_spacings) whose branch radius is known (fitted nodes
// within ten nodes up or down its chain, else at least three free fits of clearly bent arcs of
// 60 degrees or more along its chain): the slab across the local direction is fitted with a
// circle of that radius, started on the arc's concave side. The node moves to the centre when the
// inliers cover at least 60 degrees, the arc bends clearly to one side (its mirror image on the
// convex side fits a short arc almost as well: the fit starts on the concave side and must stay
// there), and the usual residual, inlier and shift tests hold. Moved nodes get fitted = 1 and the
// radius. Returns how many moved.
std::size_t fit_one_sided_sections(std::vector<Eigen::Vector3d>& pos,
                                   const std::vector<std::uint32_t>& parent,
                                   const std::vector<double>& hint,
                                   std::vector<std::uint8_t>& fitted,
                                   std::vector<double>& fitted_radius, const PointIndex& index,
                                   const std::vector<Eigen::Vector3d>& samples,
                                   const std::vector<double>& weight, const CentreLineParams& p,
                                   double noise);

}  // namespace ramus::bsg
