// Cylinders along chains (reconstruct/bsg/cylinder_fit.h, chain_cylinders.h): a half-seen,
// tilted cylinder fitted from a wrong start direction, and the one-station limb case of issue 19
// (a skeleton on the visible bark of the limbs with twig-sized radius hints, as the BSG leaves
// its spur chains along thick limbs), which cross-sections alone do not bring back to the axes.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "backends/scanner/scanner.h"
#include "core/rng.h"
#include "reconstruct/bsg/centre_line.h"
#include "reconstruct/bsg/cylinder_fit.h"
#include "tests/reconstruct/reconstruct_fixtures.h"
#include "tests/support/harness.h"

using namespace ramus;

TEST_CASE("cylinder fit: half a tilted cylinder from a start 20 degrees off", "[centre_line]") {
  Rng rng(3);
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 0.2, 0.6).normalized();
  const Eigen::Vector3d centre(0.4, -0.1, 2.0);
  const Eigen::Vector3d e1 = axis.cross(Eigen::Vector3d::UnitZ()).normalized(), e2 = axis.cross(e1);
  const double r = 0.3;
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i < 600; ++i) {
    // 160 degrees of arc: what one station sees of a limb.
    const double a = rng.uniform(-1.4, 1.4), t = rng.uniform(-0.5, 0.5);
    const double rr = r + rng.normal(0, 0.005);
    pts.push_back(centre + t * axis + rr * (std::cos(a) * e1 + std::sin(a) * e2));
  }
  // The start: a line on the bark (where a BSG chain lies), 20 degrees off the axis.
  const Eigen::Vector3d start = centre + r * e1;
  const Eigen::Vector3d d0 = (axis + std::tan(20 * M_PI / 180) * e2).normalized();
  const bsg::CylinderFit f = bsg::fit_cylinder(pts, {}, start, d0, 0.5, 0.005);
  REQUIRE(f.valid);
  const Eigen::Vector3d off = f.point - centre;
  INFO("axis offset " << (off - off.dot(axis) * axis).norm() << ", radius " << f.radius << ", cos "
                      << std::abs(f.direction.dot(axis)) << ", coverage " << f.coverage);
  CHECK((off - off.dot(axis) * axis).norm() <= 0.05 * r);
  CHECK(std::abs(f.radius - r) <= 0.05 * r);
  CHECK(std::abs(f.direction.dot(axis)) >= std::cos(3 * M_PI / 180));
  CHECK(f.coverage >= 2.5);
  CHECK(f.axial_fill >= 0.99);
  CHECK_FALSE(bsg::fit_cylinder({}, {}, start, d0, 0.5, 0.005).valid);
}

namespace {

double segment_distance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double l2 = dot(ab, ab);
  const double t = l2 > 0 ? std::clamp(dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
  return distance(p, a + ab * t);
}

// Median distance / radius of the nodes of radius >= 5 cm from the truth's axis (its nearest
// segment), after moving them onto the bark towards a single station with twig-sized hints and
// re-centring against that station's scan.
double one_station_limbs(bool chain_cylinders, bool one_sided_sections) {
  const Skeleton truth = test::thick_tree(5, 8.0, 0.3);
  scanner::ScanOptions so;
  so.from = scanner::stations_around(truth, 1);
  so.noise = 0.005;
  so.density = 6000;
  const scanner::ScanResult scan = scanner::scan_skeleton(truth, so);
  std::vector<Eigen::Vector3d> points;
  for (const Vec3f& p : scan.cloud.positions) {
    const Vec3 q = scan.cloud.offset + Vec3(p);
    points.emplace_back(q.x, q.y, q.z);
  }
  Skeleton moved = truth;
  // Twig-sized hints (above the half spacing below which nothing is fitted): a slab may then
  // not fit a circle above 6 x max(hint, 2 spacings) = 15 cm, so the trunk and the thick
  // limbs depend on the chain cylinders, as the BSG's spur chains along thick limbs do.
  for (SkeletonNode& n : moved.nodes) n.position.y -= n.radius, n.radius = 0.008;
  bsg::CentreLineParams p;
  p.spacing = 1 / std::sqrt(so.density);
  p.chain_cylinders = chain_cylinders;
  p.one_sided_sections = one_sided_sections;
  bsg::centre_skeleton(moved, points, p);
  std::vector<double> rel;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    if (truth.nodes[i].radius < 0.05) continue;
    double d = 1e9;
    for (const SkeletonNode& n : truth.nodes) {
      if (n.parent == kNoParent) continue;
      d = std::min(
          d, segment_distance(moved.nodes[i].position, truth.nodes[n.parent].position, n.position));
    }
    rel.push_back(d / truth.nodes[i].radius);
  }
  std::sort(rel.begin(), rel.end());
  return rel[rel.size() / 2];
}

}  // namespace

TEST_CASE("chain cylinders: one station, limbs with twig-sized hints return to their axes",
          "[centre_line]") {
  const double with = one_station_limbs(true, true), without = one_station_limbs(false, false);
  // The one-sided sections (one_sided_sections.h) without the cylinders: the limbs' radii come
  // from the nodes the cross-sections fitted, and their half-seen arcs then fix the axis.
  const double sections = one_station_limbs(false, true);
  INFO("median error / radius with chain cylinders " << with << ", cross-sections only " << without
                                                     << ", with one-sided sections " << sections);
  CHECK(with <= 0.15);
  CHECK(without > 2 * with);
  CHECK(without > 2 * sections);
}
