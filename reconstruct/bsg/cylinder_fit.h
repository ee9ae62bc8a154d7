// Robust cylinder fitting with a free axis direction, as TreeQSM fits its cylinders (Raumonen
// et al. 2013, Remote Sens. 5(2), section 2.3: least squares over all points of a segment, the
// axis started from the segment's direction and a circle fit). Unlike one cross-section, a
// cylinder uses every point of a stretch of branch, and a half-cylinder (a one-sided scan) still
// fixes its axis through its curvature. docs/reconstruction.md, "Centre lines".
//   1. start: the circle (circle_fit.h) of the points projected along the start direction;
//   2. Gauss-Newton on the distances |(p - q) x d| - r over the axis point q (2 dof), the
//      direction d (2 dof) and r, iteratively reweighted (Huber, then Tukey's biweight).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace ramus::bsg {

struct CylinderFit {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // on the axis, level with the points' middle
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
  double radius = 0;
  double residual = 0;         // robust scale of the inliers' distances to the surface
  double coverage = 0;         // arc the inliers cover around the axis: 2 pi minus the widest gap
  double inlier_fraction = 0;  // weight share of the inliers (within 2.5 robust scales)
  double axial_fill = 0;       // share of 8 equal bins along the inliers' axial span... of `span`
  bool valid = false;
};

// Fits a cylinder to `pts` (weights may be empty) starting from the line through `start` along
// `direction`. `span` is the half-length of the stretch the points were gathered from (for
// axial_fill: the share of 8 bins over [-span, span] around `start` that hold inliers).
CylinderFit fit_cylinder(const std::vector<Eigen::Vector3d>& pts,
                         const std::vector<double>& weights, const Eigen::Vector3d& start,
                         const Eigen::Vector3d& direction, double span, double noise,
                         int iterations = 15);

}  // namespace ramus::bsg
