#include "reconstruct/bsg/trunk_radius.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "reconstruct/bsg/circle_fit.h"

namespace ramus::bsg {

namespace {

constexpr int kSlabs = 6;
constexpr int kMinAccepted = 2;
constexpr std::size_t kMinPoints = 8;
// The centre lines' acceptance (centre_line.h, CentreLineParams): 110 degrees of arc (a scan
// from one side sees up to 180), half the points inliers, residual scale within 0.2 r.
constexpr double kMinCoverage = 1.9;
constexpr double kMinInliers = 0.5;
constexpr double kMaxResidual = 0.1;

double median_of(std::vector<double>& v) {
  const auto mid = v.begin() + std::ptrdiff_t(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// The points of `slab` within `window` of `centre`, relative to it.
void points_within(const std::vector<Eigen::Vector2d>& slab, const Eigen::Vector2d& centre,
                   double window, std::vector<Eigen::Vector2d>& out) {
  out.clear();
  for (const Eigen::Vector2d& p : slab) {
    if ((p - centre).squaredNorm() <= window * window) out.push_back(p - centre);
  }
}

bool acceptable(const CircleFit& f, double window, double spacing, double noise) {
  return f.valid && f.coverage >= kMinCoverage && f.inlier_fraction >= kMinInliers &&
         f.residual <= kMaxResidual * f.radius + noise && f.radius >= spacing &&
         f.radius <= window && f.centre.norm() <= window;
}

// The first window, from the widest down, whose circle passes; 0 when none does.
double slab_radius(const std::vector<Eigen::Vector2d>& slab, double max_width, double spacing) {
  const double noise = 0.25 * spacing;
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  std::vector<Eigen::Vector2d> pts;
  std::vector<double> xs, ys;
  for (double window = 0.5 * max_width; window >= 4 * spacing; window *= 0.5) {
    points_within(slab, centre, window, pts);
    if (pts.size() < kMinPoints) return 0.0;
    const CircleFit f = fit_circle(pts, {}, noise);
    if (acceptable(f, window, spacing, noise)) return f.radius;
    // A skirt of branches around the trunk spreads evenly on all sides: the median of what the
    // window holds stays near the trunk, and the next window is centred there.
    xs.clear(), ys.clear();
    for (const Eigen::Vector2d& p : pts) xs.push_back(p.x()), ys.push_back(p.y());
    centre += Eigen::Vector2d(median_of(xs), median_of(ys));
  }
  return 0.0;
}

}  // namespace

double trunk_radius(const std::vector<Eigen::Vector3d>& samples, const Eigen::Vector3d& base,
                    double height, double max_width, double spacing) {
  if (!(height > 0) || !(max_width > 0) || !(spacing > 0)) return 0.0;
  std::vector<std::vector<Eigen::Vector2d>> slabs(kSlabs);
  const double thickness = height / kSlabs;
  for (const Eigen::Vector3d& p : samples) {
    const Eigen::Vector2d d(p.x() - base.x(), p.y() - base.y());
    const double dz = p.z() - base.z();
    if (dz < 0 || dz >= height || d.squaredNorm() > 0.25 * max_width * max_width) continue;
    slabs[std::min(kSlabs - 1, int(dz / thickness))].push_back(d);
  }
  std::vector<double> radii;
  for (const auto& slab : slabs) {
    const double r = slab_radius(slab, max_width, spacing);
    if (r > 0) radii.push_back(r);
  }
  if (radii.size() < std::size_t(kMinAccepted)) return 0.0;
  // The lower quartile: a root flare and the clutter at the ground only ever widen a slab's
  // circle, and the quartile (not the least) keeps one slab that fitted a twig from setting it.
  std::sort(radii.begin(), radii.end());
  return radii[radii.size() / 4];
}

}  // namespace ramus::bsg
