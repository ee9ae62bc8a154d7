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
#include "reconstruct/bsg/chain_cylinders.h"
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
double one_station_limbs(bool chain_cylinders, bool one_sided_sections, bool separate_stems) {
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
  p.separate_stems = separate_stems;
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
  // "Without": cross-sections of whole slabs only (no chain cylinders, no one-sided sections, no
  // slabs split into groups).
  const double with = one_station_limbs(true, true, true),
               without = one_station_limbs(false, false, false);
  // The one-sided sections (one_sided_sections.h) without the cylinders: the limbs' radii come
  // from the nodes the cross-sections fitted, and their half-seen arcs then fix the axis.
  const double sections = one_station_limbs(false, true, false);
  INFO("median error / radius with chain cylinders " << with << ", cross-sections only " << without
                                                     << ", with one-sided sections " << sections);
  CHECK(with <= 0.15);
  CHECK(without > 2 * with);
  CHECK(without > 2 * sections);
}

TEST_CASE("bridges: a side branch's unfitted base goes onto its own axis, not the crotch's chord",
          "[centre_line]") {
  // A stem up z (nodes 0-9, fitted but for the fork at node 2, which lies 5 cm off its axis) and a
  // branch leaving the fork at 45 degrees (nodes 10-14, radius 10 cm): its first two nodes are
  // on its bark, unfitted, as the BSG leaves them where the scan sees the crotch from one side.
  const Eigen::Vector3d fork(0, 0, 2), d = Eigen::Vector3d(1, 0, 1).normalized(), bark(0, 0.08, 0);
  std::vector<Eigen::Vector3d> pos;
  std::vector<std::uint32_t> parent;
  for (int i = 0; i < 10; ++i) pos.emplace_back(0, 0, i), parent.push_back(i ? i - 1 : bsg::kNone);
  pos[2].x() = 0.05;
  for (int i = 0; i < 5; ++i) {
    pos.push_back(fork + 0.5 * (i + 1) * d + (i < 2 ? bark : Eigen::Vector3d::Zero()));
    parent.push_back(i ? 10 + i - 1 : 2);
  }
  std::vector<double> hint(15, 0.3), radius(15, 0.3);
  for (int i = 10; i < 15; ++i) hint[i] = radius[i] = 0.1;
  std::vector<std::uint8_t> fitted(15, 1);
  fitted[2] = fitted[10] = fitted[11] = 0;
  const std::vector<Eigen::Vector3d> before = pos;
  CHECK(bsg::bridge_unfitted(pos, parent, hint, fitted, radius, 0.01, 0.02) == 3);
  // The fork, on the stem's own chain, goes onto the chord between the stem's fitted nodes.
  CHECK((pos[2] - fork).norm() < 1e-9);
  const auto off_axis = [&](const Eigen::Vector3d& p) {
    const Eigen::Vector3d v = p - fork;
    return (v - v.dot(d) * d).norm();
  };
  for (int v : {10, 11}) {
    INFO("node " << v);
    CHECK(fitted[v] == 1);
    CHECK(radius[v] == 0.1);
    CHECK(off_axis(pos[v]) < 1e-9);
    CHECK((pos[v] - (fork + 0.5 * (v - 9) * d)).norm() < 1e-9);
    // The chord from the stem's fitted node below the fork (node 1) to the branch's first fitted
    // node cuts the crotch: a node projected onto it would lie 1.4-2.9 radii off the axis.
    const Eigen::Vector3d a = before[1], ab = before[12] - a;
    const Eigen::Vector3d chord = a + ((before[v] - a).dot(ab) / ab.squaredNorm()) * ab;
    CHECK(off_axis(chord) > 1.4 * 0.1);
  }
  SECTION("a fork of two stems of about the same thickness keeps the chord") {
    // Which child continues the stem below is not known there (the heaviest need not).
    pos = before;
    for (int i = 10; i < 15; ++i) radius[i] = 0.28;
    fitted.assign(15, 1);
    fitted[2] = fitted[10] = fitted[11] = 0;
    CHECK(bsg::bridge_unfitted(pos, parent, hint, fitted, radius, 0.01, 0.02) == 3);
    const Eigen::Vector3d a = before[1], ab = before[12] - a;
    for (int v : {10, 11}) {
      const double t = (before[v] - a).dot(ab) / ab.squaredNorm();
      CHECK((pos[v] - (a + t * ab)).norm() < 1e-9);
    }
  }
}

TEST_CASE(
    "bridges: the stem goes on into the child its fits and its line call for, not the heaviest",
    "[centre_line]") {
  // A trunk up z (nodes 0-2, fitted, 15 cm), an unfitted fork at node 3 lying 2 cm off the axis,
  // a leader going on up z (nodes 4-7: 4 unfitted on the bark, 5-7 fitted, 13 cm) and a limb
  // leaving at 30 degrees (nodes 8-11, fitted, 9 cm) that carries a curtain of 30 hanging twig
  // nodes, so that it is the heavier child (the weeping tree's limbs outweigh its leader). The
  // limb is thinner than a stem's continuation may be (0.09 < 0.15 / sqrt 2); the leader is not.
  const Eigen::Vector3d axis_fork(0, 0, 3), d(0.5, 0, std::sqrt(0.75));
  std::vector<Eigen::Vector3d> pos;
  std::vector<std::uint32_t> parent;
  for (int i = 0; i < 3; ++i) pos.emplace_back(0, 0, i), parent.push_back(i ? i - 1 : bsg::kNone);
  pos.emplace_back(0, -0.02, 3), parent.push_back(2);
  for (int i = 0; i < 4; ++i) pos.emplace_back(0, 0, 4 + i), parent.push_back(i ? 4 + i - 1 : 3);
  for (int i = 0; i < 4; ++i)
    pos.push_back(axis_fork + 0.5 * (i + 1) * d), parent.push_back(i ? 8 + i - 1 : 3);
  for (int i = 0; i < 30; ++i) {
    pos.push_back(pos[11] - Eigen::Vector3d(0, 0, 0.05 * (i + 1)));
    parent.push_back(i ? 12 + i - 1 : 11);
  }
  const std::size_t n = pos.size();
  std::vector<double> hint(n, 0.005), radius(n, 0.0);  // the twigs: thinner than `thin`
  std::vector<std::uint8_t> fitted(n, 0);
  for (std::uint32_t v = 0; v < 12; ++v) hint[v] = 0.15, fitted[v] = 1;
  for (std::uint32_t v : {0, 1, 2}) radius[v] = 0.15;
  for (std::uint32_t v : {5, 6, 7}) radius[v] = 0.13;
  for (std::uint32_t v : {8, 9, 10, 11}) radius[v] = 0.09;
  fitted[3] = fitted[4] = 0;
  pos[4].y() = -0.1;
  const std::vector<Eigen::Vector3d> before = pos;
  SECTION("a thicker leader that runs straight on takes the stem from a heavier, thinner limb") {
    CHECK(bsg::bridge_unfitted(pos, parent, hint, fitted, radius, 0.01, 0.02) == 2);
    // The fork and the leader's first node go onto the trunk's line: the chord from the trunk's
    // node 2 to the leader's first fitted node, not to the limb's (which passes 0.17 m, 1.2 r,
    // from the fork's place on the axis).
    CHECK((pos[3] - axis_fork).norm() < 1e-9);
    CHECK((pos[4] - Eigen::Vector3d(0, 0, 4)).norm() < 1e-9);
    CHECK(radius[3] == Approx(0.15 + (0.13 - 0.15) / 3));
  }
  // Node 3 on the chord from the trunk's node 2 to the limb's first fitted node (8): the stem
  // kept going on into the heavier child.
  const auto on_limb_chord = [&] {
    const Eigen::Vector3d a = before[2], ab = before[8] - a;
    const double t = std::clamp((before[3] - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return (pos[3] - (a + t * ab)).norm() < 1e-9;
  };
  SECTION("a heavier child fitted thick enough to go on with the stem keeps it") {
    for (std::uint32_t v : {8, 9, 10, 11}) radius[v] = 0.11;  // 0.11 > 0.15 / sqrt 2
    bsg::bridge_unfitted(pos, parent, hint, fitted, radius, 0.01, 0.02);
    CHECK(on_limb_chord());
  }
  SECTION("a straighter child that is thinner than the pipe model allows does not take it") {
    for (std::uint32_t v : {5, 6, 7}) radius[v] = 0.1;  // 0.1 < 0.15 / sqrt 2: the leader, too
    bsg::bridge_unfitted(pos, parent, hint, fitted, radius, 0.01, 0.02);
    CHECK(on_limb_chord());
  }
  SECTION("a thicker child that bends away more than the heavier one does not take it") {
    // The leader leans 60 degrees the other way, the limb 30.
    const Eigen::Vector3d lean = Eigen::Vector3d(-std::sqrt(3.0), 0, 1).normalized();
    for (int i = 0; i < 4; ++i) pos[4 + i] = axis_fork + (i + 1) * lean;
    pos[4].y() = -0.1;
    bsg::bridge_unfitted(pos, parent, hint, fitted, radius, 0.01, 0.02);
    CHECK(on_limb_chord());
  }
}
