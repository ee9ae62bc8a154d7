// The trunk radius at the base (reconstruct/bsg/trunk_radius.h), which sets the scale of every
// radius of the BSG: a clean trunk, a trunk seen from one side, a trunk inside a conifer's skirt
// of branches over cluttered ground (where a fit to all points of the base slab measured 4-5 x the
// trunk: treels_spruce 0.62 m for 0.13 m), a root flare, and points with no trunk at all.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/rng.h"
#include "reconstruct/bsg/trunk_radius.h"

using namespace ramus;

namespace {

constexpr double kSpacing = 0.01;
const Eigen::Vector3d kBase(0.0, 0.0, 0.0);

// Bark points of a vertical trunk of radius r(z) centred at `centre`, over the arc
// [from, to] (radians), every `kSpacing` or so, with 3 mm of range noise.
void add_trunk(std::vector<Eigen::Vector3d>& pts, Rng& rng, const Eigen::Vector2d& centre,
               double height, double from, double to, double r_bottom, double r_top) {
  for (double z = 0; z < height; z += kSpacing) {
    const double r = r_bottom + (r_top - r_bottom) * z / height;
    const int n = int(std::ceil((to - from) * r / kSpacing));
    for (int i = 0; i < n; ++i) {
      const double a = from + (to - from) * (i + rng.uniform01()) / n;
      const double rr = r + rng.normal(0, 0.003);
      pts.emplace_back(centre.x() + rr * std::cos(a), centre.y() + rr * std::sin(a), z);
    }
  }
}

// A conifer's skirt: branches leaving the trunk radially every few centimetres of height, each a
// line of points from the bark out to a metre, twigs scattered around them, and ground points.
void add_skirt(std::vector<Eigen::Vector3d>& pts, Rng& rng, const Eigen::Vector2d& centre,
               double trunk_r, double height) {
  for (double z = 0.02; z < height; z += 0.04) {
    for (int b = 0; b < 3; ++b) {
      const double a = rng.uniform(0, 2 * M_PI);
      for (double d = trunk_r; d < 1.0; d += kSpacing) {
        pts.emplace_back(centre.x() + d * std::cos(a) + rng.normal(0, 0.004),
                         centre.y() + d * std::sin(a) + rng.normal(0, 0.004),
                         z - 0.3 * (d - trunk_r) + rng.normal(0, 0.004));
      }
    }
  }
  for (int i = 0; i < 6000; ++i) {
    const double a = rng.uniform(0, 2 * M_PI), d = 1.1 * std::sqrt(rng.uniform01());
    pts.emplace_back(centre.x() + d * std::cos(a), centre.y() + d * std::sin(a),
                     rng.uniform(0, height));
  }
  for (int i = 0; i < 3000; ++i) {
    pts.emplace_back(rng.uniform(-1.1, 1.1), rng.uniform(-1.1, 1.1), rng.uniform(0, 0.05));
  }
}

}  // namespace

TEST_CASE("trunk radius: a clean trunk, all round and from one side", "[reconstruct]") {
  Rng rng(3);
  std::vector<Eigen::Vector3d> round, one_side;
  add_trunk(round, rng, {0.05, -0.02}, 0.6, 0, 2 * M_PI, 0.15, 0.15);
  // A scan from one side sees about half the stem, less at grazing angles.
  add_trunk(one_side, rng, {0.1, 0.0}, 0.6, -1.3, 1.3, 0.3, 0.3);
  const double r_round = bsg::trunk_radius(round, kBase, 0.6, 1.0, kSpacing);
  const double r_side = bsg::trunk_radius(one_side, kBase, 0.6, 1.6, kSpacing);
  CHECK(r_round == Approx(0.15).epsilon(0.03));
  CHECK(r_side == Approx(0.3).epsilon(0.05));
}

TEST_CASE("trunk radius: a conifer's trunk inside its skirt of branches, over many seeds",
          "[reconstruct]") {
  int found = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    Rng rng(seed);
    std::vector<Eigen::Vector3d> pts;
    const double r = 0.08 + 0.01 * double(seed % 5);
    // The base the bases stage finds sits in the clutter, off the trunk.
    const Eigen::Vector2d centre(rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3));
    add_trunk(pts, rng, centre, 0.8, 0, 2 * M_PI, r, r);
    add_skirt(pts, rng, centre, r, 0.8);
    const double got = bsg::trunk_radius(pts, kBase, 0.8, 2.4, kSpacing);
    INFO("seed " << seed << ": trunk " << r << ", measured " << got);
    CHECK(got == Approx(r).epsilon(0.1));
    found += got > 0;
  }
  CHECK(found == 20);
}

TEST_CASE("trunk radius: a root flare does not widen the trunk", "[reconstruct]") {
  Rng rng(5);
  std::vector<Eigen::Vector3d> pts;
  // 0.36 m at the ground to 0.22 m at the top of the slab (pytlidar_tree_1's base).
  add_trunk(pts, rng, {0, 0}, 0.6, 0, 2 * M_PI, 0.36, 0.22);
  const double got = bsg::trunk_radius(pts, kBase, 0.6, 1.0, kSpacing);
  CHECK(got >= 0.22);
  CHECK(got <= 0.26);
}

TEST_CASE("trunk radius: unknown without a trunk", "[reconstruct]") {
  Rng rng(7);
  std::vector<Eigen::Vector3d> scattered, few;
  for (int i = 0; i < 5000; ++i) {
    scattered.emplace_back(rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), rng.uniform(0, 0.6));
  }
  for (int i = 0; i < 5; ++i) few.emplace_back(0.1 * std::cos(i), 0.1 * std::sin(i), 0.1 * i);
  CHECK(bsg::trunk_radius(scattered, kBase, 0.6, 1.0, kSpacing) == 0);
  CHECK(bsg::trunk_radius(few, kBase, 0.6, 1.0, kSpacing) == 0);
  CHECK(bsg::trunk_radius({}, kBase, 0.6, 1.0, kSpacing) == 0);
  CHECK(bsg::trunk_radius(scattered, kBase, 0, 1.0, kSpacing) == 0);
}
