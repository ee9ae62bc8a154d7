// Cross-sections seen from one side, fitted with the branch's known radius
// (reconstruct/bsg/one_sided_sections.h): the circle on a 70-degree arc, the nodes of a limb seen
// from one side moved from its bark to its axis, a flat wall left alone, and the one-station scan
// of the bundled thick_oak (issue 19), whose 5-20 cm limbs the free-radius fits left on the bark.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "../skeleton_infer/skeleton_fixtures.h"
#include "core/rng.h"
#include "reconstruct/bsg/bsg.h"
#include "reconstruct/bsg/kdtree.h"
#include "reconstruct/bsg/one_sided_sections.h"
#include "tests/support/harness.h"

using namespace ramus;

TEST_CASE("known-radius circle: 70 degrees of arc fix the centre, given the side",
          "[centre_line]") {
  Rng rng(11);
  const double r = 0.07;
  const Eigen::Vector2d centre(0.02, 0.08);
  std::vector<Eigen::Vector2d> pts;
  for (int i = 0; i < 60; ++i) {
    const double a = -M_PI / 2 + rng.uniform(-0.61, 0.61), rr = r + rng.normal(0, 0.005);
    pts.emplace_back(centre.x() + rr * std::cos(a), centre.y() + rr * std::sin(a));
  }
  // The arc's middle is at (0.02, 0.01); the concave side is +y.
  const bsg::KnownRadiusFit in = bsg::fit_circle_known_radius(pts, {}, r, {0.02, 0.06}, 0.005);
  const bsg::KnownRadiusFit out = bsg::fit_circle_known_radius(pts, {}, r, {0.02, -0.04}, 0.005);
  REQUIRE(in.valid);
  REQUIRE(out.valid);
  INFO("from the concave side " << in.centre.transpose() << ", residual " << in.residual
                                << "; from the convex side " << out.centre.transpose()
                                << ", residual " << out.residual);
  CHECK((in.centre - centre).norm() <= 0.1 * r);
  CHECK(in.coverage >= 60 * M_PI / 180);
  CHECK(in.inlier_fraction >= 0.9);
  // The mirror circle fits almost as well: which side is the concave one must come from the
  // arc's bend (one_sided_sections.cpp), not from the fit.
  CHECK(out.centre.y() < 0.01);
  CHECK(out.residual < 1.5 * in.residual);
  CHECK_FALSE(bsg::fit_circle_known_radius({}, {}, r, {0, 0}, 0.005).valid);
}

namespace {

// A horizontal limb of radius 8 cm along x, seen from -y over 80 degrees of its bark, 1.5 cm
// spacing. Nodes every 10 cm; the first two and the last two are fitted (on the axis), the
// others lie on the bark facing the scanner, unfitted. Returns the largest distance of a middle
// node from the axis after fit_one_sided_sections, and how many moved.
std::pair<double, std::size_t> one_sided_limb(bool wall) {
  Rng rng(5);
  const double r = 0.08, spacing = 0.015;
  std::vector<Eigen::Vector3d> samples;
  for (double x = -0.1; x <= 1.1; x += spacing) {
    for (double a = -40; a <= 40; a += 180 / M_PI * spacing / r) {
      const double t = (a - 90) * M_PI / 180, rr = r + rng.normal(0, 0.004);
      // A wall: the same points flattened onto the plane y = -r.
      samples.emplace_back(x, wall ? -r + rng.normal(0, 0.004) : rr * std::cos(t),
                           wall ? rr * std::sin(t) : rr * std::sin(t));
    }
  }
  std::vector<Eigen::Vector3d> pos;
  std::vector<std::uint32_t> parent;
  std::vector<double> hint;
  std::vector<std::uint8_t> fitted;
  std::vector<double> fitted_radius;
  for (int k = 0; k <= 10; ++k) {
    const bool end = k < 2 || k > 8;
    pos.emplace_back(0.1 * k, end ? 0.0 : -r, 0.0);
    parent.push_back(k == 0 ? bsg::kNone : std::uint32_t(k - 1));
    hint.push_back(0.04);  // the allometric hint: half the truth, as on thick_oak
    fitted.push_back(end);
    fitted_radius.push_back(end ? r : 0.0);
  }
  bsg::CentreLineParams p;
  p.spacing = spacing;
  const bsg::PointIndex index(samples);
  const std::size_t moved = bsg::fit_one_sided_sections(pos, parent, hint, fitted, fitted_radius,
                                                        index, samples, {}, p, 0.25 * spacing);
  double worst = 0;
  for (int k = 2; k <= 8; ++k) worst = std::max(worst, std::hypot(pos[k].y(), pos[k].z()));
  return {worst, moved};
}

}  // namespace

TEST_CASE("one-sided sections: a limb's bark nodes move to its axis, a wall's stay",
          "[centre_line]") {
  const auto [limb, limb_moved] = one_sided_limb(false);
  INFO("limb: worst distance from the axis " << limb << " m, moved " << limb_moved);
  CHECK(limb_moved == 7);
  CHECK(limb <= 0.15 * 0.08);
  const auto [wall, wall_moved] = one_sided_limb(true);
  INFO("wall: moved " << wall_moved);
  CHECK(wall_moved == 0);
}

// thick_oak (examples/trees) from one station. Measured (median centre-line error / radius over
// all truth samples): 5-10 cm 0.451 -> 0.315, 10-20 cm 0.582 -> 0.406 with the one-sided
// sections and the second round of bridges; the 0.15 is not met (docs/reconstruction.md,
// Centre lines). The bounds lie between the two.
TEST_CASE("one-sided sections: thick_oak from one station, 5-20 cm limbs nearer their axes",
          "[accuracy]") {
  scanner::HarnessCase c;
  c.stations = 1;
  const scanner::HarnessResult r =
      scanner::run_harness_on_grammar(RAMUS_SOURCE_DIR "/examples/trees/thick_oak.ramus", c);
  REQUIRE(r.trees == 1);
  const SkeletonComparison& a = r.at_radius;
  CHECK(a.precision >= 0.95);
  // Over the wood the scan saw (CompareOptions::scan; 61 % of the truth's samples): recall 0.983,
  // median error / radius 0.091 / 0.114 in the classes 5-10 / 10-20 cm.
  INFO("seen " << a.seen_fraction << " recall seen " << a.recall_seen);
  CHECK(a.seen_fraction > 0.5);
  CHECK(a.seen_fraction < 0.75);
  CHECK(a.recall_seen >= 0.95);
  // Per class: the bound over all samples, and over the seen ones. (The 20-40 cm class is
  // checked at six azimuths below: from this one its median is 0.194 r over the seen wood, from
  // the other five 0.028-0.135.)
  struct Bound {
    double lo, hi, all, seen;
  };
  for (const Bound& b : {Bound{0.05, 0.1, 0.37, 0.15}, Bound{0.1, 0.2, 0.48, 0.25}}) {
    for (const CentreError& e : a.centre_error) {
      if (e.lo < b.lo || e.hi > b.hi + 1e-9) continue;
      INFO("radii " << e.lo << "-" << e.hi << ": median " << e.median << " (n " << e.samples
                    << "), seen " << e.median_seen << " (n " << e.seen << ")");
      CHECK(e.median <= b.all);
      CHECK(e.median_seen <= b.seen);
    }
  }
}

// thick_oak turned to six azimuths, one station each: the seen medians of the 5-10, 10-20 and
// 20-40 cm classes, 18 in all. Before forks were kept from walking along their lighter child in
// the edge removal (reconstruct/bsg/inflate.cpp, kForkDrift) two were above 0.15 (the 20-40 cm
// stems at 120 and 180 degrees, 0.217 and 0.218 r); now one is (20-40 cm at 0 degrees, 0.194 r,
// 0.074 before) and none above 0.2.
TEST_CASE("one-sided sections: thick_oak from one station at six azimuths", "[accuracy]") {
  const Skeleton grown = skeleton_test::grow_example("examples/trees/thick_oak.ramus");
  REQUIRE(grown.size() > 1);
  int above = 0, classes = 0;
  for (int azimuth = 0; azimuth < 360; azimuth += 60) {
    Skeleton truth = grown;
    scanner::turn_about_root(truth, azimuth);
    scanner::HarnessCase c;
    c.stations = 1;
    const scanner::HarnessResult r = scanner::run_harness(truth, c);
    REQUIRE(r.trees == 1);
    for (const CentreError& e : r.at_radius.centre_error) {
      if (e.lo < 0.05 - 1e-9 || e.hi > 0.4 + 1e-9 || e.seen == 0) continue;
      INFO("azimuth " << azimuth << ", radii " << e.lo << "-" << e.hi << ": median seen "
                      << e.median_seen << " (n " << e.seen << ")");
      CHECK(e.median_seen <= 0.2);
      above += e.median_seen > 0.15;
      ++classes;
    }
  }
  CHECK(classes == 18);
  CHECK(above <= 1);
}
