// Centre lines (reconstruct/bsg/centre_line.h, circle_fit.h): the circle fit on full and partial
// arcs with outliers, and skeleton nodes put on the bark of a scanned thick tree coming back to
// its axis.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <sstream>
#include <string>

#include "backends/scanner/scanner.h"
#include "core/rng.h"
#include "reconstruct/bsg/centre_line.h"
#include "reconstruct/bsg/circle_fit.h"
#include "tests/reconstruct/bsg_fixtures.h"
#include "tests/reconstruct/reconstruct_fixtures.h"
#include "tests/support/harness.h"

using namespace ramus;

namespace {

// Points on an arc of `span` radians of the circle (c, r), with radial noise, plus outliers.
std::vector<Eigen::Vector2d> arc(Eigen::Vector2d c, double r, double span, int n, double noise,
                                 int outliers, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<Eigen::Vector2d> pts;
  for (int i = 0; i < n; ++i) {
    const double a = rng.uniform(-span / 2, span / 2), rr = r + rng.normal(0, noise);
    pts.emplace_back(c.x() + rr * std::cos(a), c.y() + rr * std::sin(a));
  }
  for (int i = 0; i < outliers; ++i) {
    pts.emplace_back(c.x() + rng.uniform(-2 * r, 3 * r), c.y() + rng.uniform(-2 * r, 2 * r));
  }
  return pts;
}

}  // namespace

TEST_CASE("circle fit: full, half and quarter arcs with noise", "[centre_line]") {
  const Eigen::Vector2d c(1.5, -0.7);
  for (double span : {2 * M_PI, M_PI, M_PI / 2}) {
    for (double r : {0.05, 0.3, 0.6}) {
      const auto pts = arc(c, r, span, 200, 0.005, 0, 3);
      const bsg::CircleFit f = bsg::fit_circle(pts, {}, 0.0025);
      INFO("span " << span << " r " << r << ": fitted " << f.radius << " centre error "
                   << (f.centre - c).norm());
      REQUIRE(f.valid);
      // A quarter arc of a 5 cm circle with 5 mm noise is the hardest: 0.25 r.
      CHECK((f.centre - c).norm() <= (span > 2 ? 0.05 : 0.25) * r + 0.002);
      CHECK(std::abs(f.radius - r) <= (span > 2 ? 0.05 : 0.25) * r + 0.002);
      CHECK(f.coverage >= 0.9 * span - 0.1);
    }
  }
}

TEST_CASE("circle fit: a third of the points from another branch do not pull it", "[centre_line]") {
  const Eigen::Vector2d c(0, 0);
  auto pts = arc(c, 0.3, M_PI, 300, 0.004, 0, 5);
  // A thinner branch beside it: a tight cluster of points 0.5 m away.
  const auto other = arc({0.5, 0.3}, 0.06, 2 * M_PI, 150, 0.004, 0, 6);
  pts.insert(pts.end(), other.begin(), other.end());
  const bsg::CircleFit taubin = bsg::taubin_circle(pts, {});
  const bsg::CircleFit f = bsg::fit_circle(pts, {}, 0.002);
  INFO("Taubin centre error " << taubin.centre.norm() << ", robust " << f.centre.norm());
  CHECK(f.centre.norm() < 0.03);
  CHECK(std::abs(f.radius - 0.3) < 0.03);
  CHECK(f.inlier_fraction < 0.8);
}

TEST_CASE("circle fit: degenerate input is invalid, never NaN", "[centre_line]") {
  CHECK_FALSE(bsg::fit_circle({}, {}, 0.01).valid);
  CHECK_FALSE(bsg::fit_circle({{0, 0}, {1, 1}}, {}, 0.01).valid);
  std::vector<Eigen::Vector2d> line;
  for (int i = 0; i < 50; ++i) line.emplace_back(0.01 * i, 0.02 * i);
  const bsg::CircleFit f = bsg::fit_circle(line, {}, 0.001);
  CHECK((!f.valid || std::isfinite(f.radius)));
  std::vector<Eigen::Vector2d> same(30, Eigen::Vector2d(1, 1));
  CHECK_FALSE(bsg::fit_circle(same, {}, 0.001).valid);
}

TEST_CASE("two arcs: touching arcs of two limbs come apart, one stem's arc stays whole",
          "[centre_line]") {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    INFO("seed " << seed);
    // Two limbs of radius 0.15 and 0.12, axes 0.24 m apart, each seen from below (y < 0).
    auto pts = arc({-0.12, 0}, 0.15, 2 * M_PI, 120, 0.003, 0, seed);
    auto other = arc({0.12, 0}, 0.12, 2 * M_PI, 100, 0.003, 0, seed + 100);
    pts.insert(pts.end(), other.begin(), other.end());
    for (Eigen::Vector2d& q : pts) q.y() = -std::abs(q.y());
    // One circle through all of them (the algebraic one: between the limbs).
    const bsg::CircleFit whole = bsg::taubin_circle(pts, {});
    bsg::CircleFit a, b;
    REQUIRE(bsg::split_two_arcs(pts, {}, whole, 0.0025, a, b));
    if (a.centre.x() > b.centre.x()) std::swap(a, b);
    CHECK((a.centre - Eigen::Vector2d(-0.12, 0)).norm() <= 0.02);
    CHECK(std::abs(a.radius - 0.15) <= 0.02);
    CHECK((b.centre - Eigen::Vector2d(0.12, 0)).norm() <= 0.02);
    CHECK(std::abs(b.radius - 0.12) <= 0.02);
    // One stem's half arc: one circle fits it, and no split is taken.
    const auto half = arc({0.3, 0.1}, 0.2, M_PI, 200, 0.003, 0, seed + 200);
    const bsg::CircleFit one = bsg::fit_circle(half, {}, 0.0025);
    CHECK_FALSE(bsg::split_two_arcs(half, {}, one, 0.0025, a, b));
  }
}

TEST_CASE("robust scale: 1.4826 x the median absolute value, with ties and many sizes",
          "[centre_line]") {
  // robust_scale selects the median without sorting (a quickselect of its own); it must return
  // exactly the order statistic a sort gives, ties and repeated values included.
  Rng rng(17);
  CHECK(bsg::robust_scale({}) == 0.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const std::size_t n = 1 + rng.below(trial % 4 == 0 ? 400 : 40);
    std::vector<double> e(n);
    for (double& x : e) {
      // Every third array holds few distinct values (many ties), the others signed normals.
      x = trial % 3 == 0 ? double(rng.below(4)) - 2.0 : rng.normal(0, 1 + rng.below(3));
    }
    std::vector<double> sorted = e;
    for (double& x : sorted) x = std::abs(x);
    std::sort(sorted.begin(), sorted.end());
    INFO("n " << n << " trial " << trial);
    REQUIRE(bsg::robust_scale(e) == 1.4826 * sorted[n / 2]);
  }
}

namespace {

double segment_distance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double l2 = dot(ab, ab);
  const double t = l2 > 0 ? std::clamp(dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
  return distance(p, a + ab * t);
}

double axis_distance(const Skeleton& s, std::uint32_t v, const Vec3& p) {
  double d = distance(p, s.nodes[v].position);
  if (s.nodes[v].parent != kNoParent)
    d = std::min(d, segment_distance(p, s.nodes[s.nodes[v].parent].position, s.nodes[v].position));
  for (std::uint32_t c = 0; c < s.size(); ++c) {
    if (s.nodes[c].parent == v)
      d = std::min(d, segment_distance(p, s.nodes[v].position, s.nodes[c].position));
  }
  return d;
}

// The truth's nodes moved onto the bark (by their radius, sideways), re-centred against a scan.
// Returns the median of |centred - truth| / radius over nodes of radius >= 5 cm, and the share
// of those nodes fitted.
std::pair<double, double> recentre_truth(int stations) {
  const Skeleton truth = test::thick_tree(5, 8.0, 0.3);
  scanner::ScanOptions so;
  so.from = scanner::stations_around(truth, stations);
  so.noise = 0.005;
  so.density = 1500;
  const scanner::ScanResult scan = scanner::scan_skeleton(truth, so);
  std::vector<Eigen::Vector3d> points;
  for (const Vec3f& p : scan.cloud.positions) {
    const Vec3 q = scan.cloud.offset + Vec3(p);
    points.emplace_back(q.x, q.y, q.z);
  }
  Skeleton moved = truth;
  // Towards the station of a one-sided scan (-y): the node lies on the visible bark.
  for (SkeletonNode& n : moved.nodes) n.position.y -= n.radius, n.radius *= 0.5;
  bsg::CentreLineParams p;
  p.spacing = 1 / std::sqrt(so.density);
  bsg::centre_skeleton(moved, points, p);
  std::vector<double> rel;
  std::size_t thick = 0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    if (truth.nodes[i].radius < 0.05) continue;
    ++thick;
    // The fit moves a node across its branch, not along it: the error is the distance to the
    // truth's axis (the segments at the node).
    rel.push_back(axis_distance(truth, std::uint32_t(i), moved.nodes[i].position) /
                  truth.nodes[i].radius);
  }
  std::sort(rel.begin(), rel.end());
  std::size_t within = 0;
  for (double e : rel) within += e < 0.5;
  return {rel[rel.size() / 2], double(within) / double(thick)};
}

}  // namespace

TEST_CASE("centre line: nodes on the bark of a scanned thick tree move to its axis",
          "[centre_line]") {
  for (int stations : {3, 1}) {
    const auto [median, within] = recentre_truth(stations);
    INFO(stations << " stations: median error / radius " << median << ", within 0.5 r " << within);
    CHECK(median <= 0.15);
    CHECK(within >= 0.7);
  }
}

TEST_CASE("centre line: a root on the bark below a fitted stem goes onto its axis",
          "[centre_line]") {
  // The front half of a 30 cm stem, scanned from 0.1 m up; the root on the bark at the ground
  // (the base finder's vertex nearest the footprint's centroid), the chain above it on the bark.
  Rng rng(41);
  std::vector<Eigen::Vector3d> bark;
  for (int i = 0; i < 20000; ++i) {
    const double a = rng.uniform(-M_PI, 0), z = rng.uniform(0.1, 2.0);
    const double rr = 0.3 + rng.normal(0, 0.002);
    bark.emplace_back(rr * std::cos(a), rr * std::sin(a), z);
  }
  std::vector<Eigen::Vector3d> pos{{0, -0.3, 0}};
  std::vector<std::uint32_t> parent{bsg::kNone};
  std::vector<double> hint{0.3};
  for (int k = 1; k <= 8; ++k) {
    pos.emplace_back(0.02, -0.29, 0.2 * k);
    parent.push_back(std::uint32_t(k - 1));
    hint.push_back(0.3);
  }
  bsg::CentreLineParams p;
  p.spacing = 0.01;
  // The cross-sections alone: the root's slab holds no point, and nothing else may place it.
  p.chain_cylinders = false;
  p.one_sided_sections = false;
  const bsg::PointIndex index(bark);
  const bsg::CentreLineResult fit = bsg::centre_line(pos, parent, hint, bark, index, {}, p);
  INFO("root at " << pos[0].transpose());
  CHECK(fit.fitted[0]);
  CHECK(std::hypot(pos[0].x(), pos[0].y()) < 0.03);
  CHECK(std::abs(pos[0].z()) < 0.03);
}

// A stem of 20 cm whose bark above 1 m stands 1.25 x as far off its axis (as a slab across two
// limbs pressed together after a fork measures): a cross-section does not thicken its stem by
// more than 1.15 x (CentreLineParams::max_section_growth), so the nodes above 1 m keep no
// circle; with the earlier bound of 1.3 they took the thicker one. (The bound holds from node to
// node: a node on the step itself would measure between the two, and the next from there.)
namespace {

std::size_t fitted_above_a_swelling(double max_section_growth) {
  Rng rng(29);
  std::vector<Eigen::Vector3d> bark;
  for (int i = 0; i < 30000; ++i) {
    const double a = rng.uniform(0, 2 * M_PI), z = rng.uniform(0, 2);
    const double rr = (z < 1 ? 0.2 : 0.25) + rng.normal(0, 0.002);
    bark.emplace_back(rr * std::cos(a), rr * std::sin(a), z);
  }
  std::vector<Eigen::Vector3d> pos;
  std::vector<std::uint32_t> parent;
  std::vector<double> hint;
  for (int k = 0; k < 18; ++k) {
    pos.emplace_back(0.02, -0.01, 0.05 + 0.1 * k);  // none on the step at 1 m
    parent.push_back(k == 0 ? bsg::kNone : std::uint32_t(k - 1));
    hint.push_back(0.2);
  }
  bsg::CentreLineParams p;
  p.spacing = 0.01;
  p.max_section_growth = max_section_growth;
  p.chain_cylinders = false;  // the cross-sections alone
  p.one_sided_sections = false;
  p.continuation_fits = false;
  const bsg::PointIndex index(bark);
  const bsg::CentreLineResult fit = bsg::centre_line(pos, parent, hint, bark, index, {}, p);
  std::size_t above = 0;
  for (std::size_t v = 0; v < pos.size(); ++v) above += fit.fitted[v] && pos[v].z() > 1;
  return above;
}

}  // namespace

TEST_CASE("centre line: a cross-section does not thicken its stem by more than 1.15 x",
          "[centre_line]") {
  CHECK(fitted_above_a_swelling(bsg::CentreLineParams{}.max_section_growth) == 0);
  CHECK(fitted_above_a_swelling(1.3) >= 6);  // of 8
}

// A 20 cm stem seen from one side (the front half, y < 0), and the chain a scan of a conifer
// gives it: straight up the front bark at first, then zigzagging 30 cm left and right every few
// nodes (the shortest paths step from whorl to whorl), so that the direction from two nodes down
// to two up leans 40-60 degrees off the stem and every slab across it cuts an ellipse. The
// continuation fits cut the zigzag's nodes across the axis of the fitted stem below.
namespace {

struct ZigzagResult {
  std::size_t fitted = 0;  // zigzag nodes fitted
  double worst = 0;        // largest distance of a fitted zigzag node from the axis
};

ZigzagResult centre_zigzag(bool continuation) {
  const double r = 0.2;
  Rng rng(17);
  std::vector<Eigen::Vector3d> bark;
  for (int i = 0; i < 20000; ++i) {
    const double a = rng.uniform(M_PI, 2 * M_PI), z = rng.uniform(0, 3);
    const double rr = r + rng.normal(0, 0.003);
    bark.emplace_back(rr * std::cos(a), rr * std::sin(a), z);
  }
  std::vector<Eigen::Vector3d> pos;
  std::vector<std::uint32_t> parent;
  for (int k = 0; k < 28; ++k) {
    const double z = 0.1 + 0.1 * k;
    const double x = k < 9 ? 0.0 : 0.3 * std::sin(2 * M_PI * (k - 9) / 6.0);
    pos.emplace_back(x, -r, z);
    parent.push_back(k == 0 ? bsg::kNone : std::uint32_t(k - 1));
  }
  const std::vector<double> hint(pos.size(), r);
  bsg::CentreLineParams p;
  p.spacing = 0.01;
  p.continuation_fits = continuation;
  p.chain_cylinders = false;  // the slabs alone: what the continuation adds to them
  p.one_sided_sections = false;
  const bsg::PointIndex index(bark);
  const bsg::CentreLineResult fit = bsg::centre_line(pos, parent, hint, bark, index, {}, p);
  ZigzagResult out;
  for (std::size_t v = 9; v < pos.size() - 2; ++v) {
    if (!fit.fitted[v]) continue;
    ++out.fitted;
    out.worst = std::max(out.worst, std::hypot(pos[v].x(), pos[v].y()));
  }
  return out;
}

}  // namespace

TEST_CASE("centre line: a zigzag chain up a half-seen stem is cut across the stem's axis",
          "[centre_line]") {
  const ZigzagResult with = centre_zigzag(true), without = centre_zigzag(false);
  INFO("zigzag nodes fitted: " << with.fitted << " (without continuation fits " << without.fitted
                               << "), farthest from the axis " << with.worst);
  CHECK(with.fitted >= 14);  // of 17 (measured: 17; without the continuation fits 1)
  CHECK(with.fitted >= without.fitted + 8);
  CHECK(with.worst <= 0.25 * 0.2);
}

TEST_CASE("centre line: a copy of the trunk hung from a limb's base goes, a twig from it stays",
          "[centre_line]") {
  // A trunk (radius 0.2) up z, a limb (radius 0.1) from its node at z = 1 out along x, both
  // fitted. From the limb's first node hang: a chain that crosses back (two nodes outside both
  // stems) and runs up inside the trunk, as the shortest paths of a one-station scan do; and a
  // chain that crosses the same way but leaves the trunk again at its tip.
  bsg::Bsg b;
  std::vector<std::uint8_t> fitted;
  auto add = [&](Eigen::Vector3d p, std::uint32_t parent, double r, bool fit) {
    fitted.push_back(fit);
    return test::add_bsg_node(b, p, parent, r);
  };
  std::uint32_t up = bsg::kNone;
  for (int k = 0; k <= 5; ++k) up = add({0, 0, 0.5 * k}, up, 0.2, true);
  const std::uint32_t limb = add({0.5, 0, 1.2}, 2, 0.1, true);
  add({1.0, 0, 1.4}, limb, 0.1, true);
  auto crossing = [&](bool leaves) {
    std::uint32_t v = add({0.45, 0, 1.35}, limb, 0.05, false);
    v = add({0.3, 0, 1.45}, v, 0.05, false);
    for (int k = 0; k < 6; ++k) v = add({0.1, 0, 1.55 + 0.15 * k}, v, 0.05, false);
    if (leaves) add({0.6, 0, 2.4}, v, 0.05, false);
  };
  crossing(false);  // 8 nodes, 2 outside: goes
  crossing(true);   // its tip outside the trunk: stays
  const std::size_t before = b.size();
  CHECK(bsg::drop_branches_inside_stems(b, fitted, 0.01) == 8);
  REQUIRE(b.size() == before - 8);
  CHECK(b.pos.back().isApprox(Eigen::Vector3d(0.6, 0, 2.4)));
  CHECK(b.parent[8] == limb);  // the survivor's first node, renumbered after the removal
}

TEST_CASE("centre line: with the containers given, only the leaf chains whose tips may go go",
          "[centre_line]") {
  // A stem (radius 0.2) up z with no fits, and from its node at z = 0.5 two leaf chains up
  // inside it, 5 cm from its axis. Every edge is a container here; only the second chain's tip
  // is flagged, so only the second chain goes (its three nodes).
  bsg::Bsg b;
  std::uint32_t up = bsg::kNone;
  for (int k = 0; k <= 5; ++k) up = test::add_bsg_node(b, {0, 0, 0.5 * k}, up, 0.2);
  std::vector<std::uint32_t> tips;
  for (double x : {0.05, -0.05}) {
    std::uint32_t v = 1;
    for (int k = 1; k <= 3; ++k) v = test::add_bsg_node(b, {x, 0, 0.5 + 0.3 * k}, v, 0.02);
    tips.push_back(v);
  }
  std::vector<std::uint8_t> tip_may_go(b.size(), 0);
  tip_may_go[tips[1]] = 1;
  const std::vector<std::uint8_t> every_edge(b.size(), 1);
  bsg::Bsg kept = b;
  CHECK(bsg::drop_chains_inside_edges(kept, every_edge, tip_may_go, 0.01) == 3);
  REQUIRE(kept.size() == b.size() - 3);
  for (const auto& p : kept.pos) CHECK(p.x() >= 0);
  // No containers: nothing goes.
  bsg::Bsg none = b;
  CHECK(bsg::drop_chains_inside_edges(none, std::vector<std::uint8_t>(b.size(), 0),
                                      std::vector<std::uint8_t>(b.size(), 1), 0.01) == 0);
  CHECK(none.size() == b.size());
}

// Two limbs (radius 0.15, tapering) leave a stem (radius 0.2) side by side, 0.4 m apart, and are
// scanned from one side; the skeleton's chain runs up between them, as the shortest paths of a
// BSG that merged the two do. No circle fits a slab across both; the group of points nearest each
// node does, and it continues the stem below (pipe model: between 0.71 and 1 x 0.2). With the
// limbs' axes closer (leaving the fork together, moving apart up the limbs) their arcs touch, no
// gap parts the groups, and the slab's points are split into two arcs instead.
namespace {

struct TwoLimbResult {
  std::size_t fitted = 0;   // chain nodes between the limbs that were fitted
  double worst = 0;         // the farthest of them from the nearer limb's axis
  std::size_t on_limb = 0;  // chain nodes within 0.15 x the radius of that axis
};

TwoLimbResult centre_two_limbs(bool separate, bool split, double x_limb, double lean) {
  const double r_stem = 0.2, r_limb = 0.15;
  Rng rng(23);
  std::vector<Eigen::Vector3d> bark;
  // Limbs taper by a fifth over their length, as branches do.
  // `lean`: the limbs' axes move apart by this much per metre up.
  auto half_seen = [&](double cx, double lean_x, double r, double z0, double z1, int n) {
    for (int i = 0; i < n; ++i) {
      const double a = rng.uniform(M_PI, 2 * M_PI), z = rng.uniform(z0, z1);
      const double rr = r * (1 - 0.2 * (z - z0) / (z1 - z0)) + rng.normal(0, 0.003);
      bark.emplace_back(cx + lean_x * (z - z0) + rr * std::cos(a), rr * std::sin(a), z);
    }
  };
  half_seen(0, 0, r_stem, 0, 1, 15000);
  half_seen(-x_limb, -lean, r_limb, 1, 2.5, 15000);
  half_seen(x_limb, lean, r_limb, 1, 2.5, 15000);
  std::vector<Eigen::Vector3d> pos;
  std::vector<std::uint32_t> parent;
  std::vector<double> hint;
  for (int k = 0; k < 24; ++k) {
    const double z = 0.1 + 0.1 * k;
    // On the stem's bark, then between the limbs, nearer the right one (at 3/7 of its axis's x).
    const double x = (x_limb + lean * (z - 1)) * 3 / 7;
    pos.push_back(z < 1 ? Eigen::Vector3d(0, -r_stem, z) : Eigen::Vector3d(x, -0.12, z));
    parent.push_back(k == 0 ? bsg::kNone : std::uint32_t(k - 1));
    hint.push_back(r_stem);
  }
  bsg::CentreLineParams p;
  p.spacing = 0.01;
  p.separate_stems = separate;
  p.split_arcs = split;
  p.chain_cylinders = false;  // the slabs alone
  p.one_sided_sections = false;
  const bsg::PointIndex index(bark);
  const bsg::CentreLineResult fit = bsg::centre_line(pos, parent, hint, bark, index, {}, p);
  TwoLimbResult out;
  for (std::size_t v = 0; v < pos.size(); ++v) {
    if (pos[v].z() < 1.15 || pos[v].z() > 2.35) continue;  // the slabs that see both limbs whole
    const double x = x_limb + lean * (pos[v].z() - 1);     // the limbs' axes at this height
    const double off =
        std::min(std::hypot(pos[v].x() - x, pos[v].y()), std::hypot(pos[v].x() + x, pos[v].y()));
    out.on_limb += off <= 0.15 * r_limb;
    if (!fit.fitted[v]) continue;
    ++out.fitted;
    out.worst = std::max(out.worst, off);
  }
  return out;
}

std::string describe(const TwoLimbResult& with, const TwoLimbResult& without) {
  std::ostringstream o;
  o << "fitted " << with.fitted << " (without " << without.fitted << "), on a limb's axis "
    << with.on_limb << " (without " << without.on_limb << "), farthest " << with.worst;
  return o.str();
}

}  // namespace

TEST_CASE("centre line: a chain between two limbs side by side goes onto the nearer limb's axis",
          "[centre_line]") {
  const TwoLimbResult with = centre_two_limbs(true, false, 0.35, 0),
                      without = centre_two_limbs(false, false, 0.35, 0);
  INFO(describe(with, without));
  CHECK(with.on_limb >= 8);  // of 12 (measured: 12)
  CHECK(without.on_limb == 0);
  CHECK(with.worst <= 0.2 * 0.15);
}

TEST_CASE(
    "centre line: a chain between two limbs whose arcs touch goes onto the nearer limb's axis",
    "[centre_line]") {
  // The limbs' axes 0.2 m apart at the fork and 0.2 m further apart per metre up: over the
  // lower half of the chain the two arcs run into each other.
  const TwoLimbResult with = centre_two_limbs(true, true, 0.1, 0.1),
                      without = centre_two_limbs(true, false, 0.1, 0.1);
  INFO(describe(with, without));
  CHECK(with.on_limb >= 9);  // of 12 (measured: 11; without the split 4)
  CHECK(without.on_limb <= 6);
  CHECK(with.worst <= 0.15 * 0.15);
}
