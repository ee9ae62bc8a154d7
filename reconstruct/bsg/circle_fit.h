// Robust circle fitting in a plane: the cross-section of a branch, as TreeQSM (Raumonen et al.
// 2013, Remote Sens. 5(2), section 2.3: least-squares cylinders after an algebraic start) and
// AdTree (Du et al. 2019, Remote Sens. 11(18), section 3.3: radii from fitted cross-sections)
// fit their cylinders. docs/reconstruction.md, "Centre lines".
//   1. algebraic start: Taubin's fit (Taubin 1991, IEEE PAMI 13(11); the Newton form of Chernov,
//      "Circular and linear regression", 2010, ch. 5), which unlike Kasa's is not biased towards
//      small circles on a partial arc;
//   2. geometric fit: Gauss-Newton on the distances |p - c| - r, iteratively reweighted (Huber
//      first, then Tukey's biweight), so that points of another branch in the slab, or the
//      noise of a rough bark, do not pull the circle.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace ramus::bsg {

struct CircleFit {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 0;
  double residual = 0;  // robust scale (1.4826 MAD) of the inliers' distances to the circle
  double coverage = 0;  // angle (radians) of the arc the inliers cover: 2 pi minus the widest gap
  double inlier_fraction = 0;  // weight share of the points with a non-zero final Tukey weight
  bool valid = false;          // finite and non-degenerate
};

// 1.4826 x the median of |e|: the standard deviation of Gaussian residuals, robustly.
double robust_scale(const std::vector<double>& e);
// The same, reusing e's storage (its values are lost).
double robust_scale_in_place(std::vector<double>& e);

// The iteratively reweighted least-squares weight of a residual of u robust scales: Huber's
// (k 1.345, a convex start) or, once the fit has settled, Tukey's biweight (c 4.685, outliers get
// weight 0). Shared by the circle and the cylinder fits.
double robust_weight(double u, bool tukey);

// 2 pi minus the widest gap between the given angles (radians, any order): the arc they cover.
// Sorts `angles` in place.
double angular_coverage(std::vector<double>& angles);

// Taubin's algebraic circle through weighted points (weights may be empty: all 1).
CircleFit taubin_circle(const std::vector<Eigen::Vector2d>& pts,
                        const std::vector<double>& weights);

// The robust geometric fit, started from Taubin's. `noise` floors the residual scale (the range
// noise of the scanner, or a fraction of the point spacing): without it, a near-perfect arc would
// make every point but the best few an outlier.
CircleFit fit_circle(const std::vector<Eigen::Vector2d>& pts, const std::vector<double>& weights,
                     double noise, int iterations = 12);

// Two circles for points on two arcs that touch: a slab across two limbs just after their fork,
// each limb seen on one side, where no gap parts the arcs and one circle fitted to all of them
// (`whole`) lies between the limbs. Ordered by angle around whole's centre, the points of one
// arc come before those of the other; the split is tried at every sixteenth of the points, each
// side fitted algebraically (Taubin), and the split whose circles lie nearest their points (the
// sum over both sides of the median distance, per point) is taken when that is below half the
// median distance to `whole`, and `whole` misses its points by more than twice the noise (a
// single stem's arc is fitted about as well by one circle as by two). Returns false when no
// split is taken; else the robust fits (fit_circle) of the two sides.
bool split_two_arcs(const std::vector<Eigen::Vector2d>& pts, const std::vector<double>& weights,
                    const CircleFit& whole, double noise, CircleFit& first, CircleFit& second);

}  // namespace ramus::bsg
