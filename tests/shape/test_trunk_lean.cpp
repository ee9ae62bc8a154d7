// Trunk lean (infer/shape/trunk_lean.h): the same angle from a skeleton and from a scan of its
// bark, undisturbed by side branches.
#include <catch2/catch.hpp>
#include <cmath>

#include "infer/shape/tree_shape.h"
#include "infer/shape/trunk_lean.h"
#include "shape_fixtures.h"

using namespace ramus;
using namespace shape_test;

namespace {

// A trunk of length 10 leaning `lean` degrees towards azimuth `azimuth`, with a crown of
// branches from 0.4 of its length and, at 0.2, drooping twigs that fill the lean band with
// more samples than the trunk has there.
Skeleton leaning_tree(double lean, double azimuth) {
  Skeleton s;
  const Vec3 dir = tilted(lean, azimuth);
  const std::uint32_t low = chain(s, {0, 0, 0}, dir * 2.0, 8);
  const std::uint32_t mid = chain(s, dir * 2.0, dir * 4.0, 8, low);
  chain(s, dir * 4.0, dir * 10.0, 12, mid);
  for (int k = 0; k < 3; ++k) {  // drooping twigs on one side, from 2 down by about 0.5
    const Vec3 out = dir * 2.0 + tilted(100, azimuth + 40.0 * k) * 3.0;
    chain(s, dir * 2.0, out, 6, low);
  }
  for (int k = 0; k < 5; ++k) chain(s, dir * 4.0, dir * 4.0 + tilted(50, 72.0 * k) * 4.0, 4, mid);
  return s;
}

// Bark points on a cylinder of radius `radius` around the segment from a to b.
std::vector<Vec3> bark(Vec3 a, Vec3 b, double radius, int rings, int around) {
  const Vec3 axis = normalized(b - a);
  const Vec3 u = normalized(cross(axis, std::abs(axis.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0}));
  const Vec3 v = cross(axis, u);
  std::vector<Vec3> out;
  for (int i = 0; i <= rings; ++i) {
    const Vec3 c = a + (b - a) * (double(i) / rings);
    for (int j = 0; j < around; ++j) {
      const double t = 2 * kPi * (j + 0.5 * (i % 2)) / around;
      out.push_back(c + u * (radius * std::cos(t)) + v * (radius * std::sin(t)));
    }
  }
  return out;
}

}  // namespace

TEST_CASE("trunk lean: a tree tilted by 20 degrees measures 20", "[shape]") {
  for (double azimuth : {0.0, 35.0, 200.0}) {
    INFO(azimuth);
    const Skeleton tree = leaning_tree(20, azimuth);
    CHECK(shape::measure_tree_shape(tree).lean_degrees == Approx(20).margin(0.5));
  }
  CHECK(shape::lean_degrees(leaning_tree(0, 0)) == Approx(0).margin(0.5));
  CHECK(shape::lean_degrees(leaning_tree(35, 120)) == Approx(35).margin(1.0));
  // So far over that a vertical start loses it in the first slice: the line fitted to the
  // lowest 5 % finds it.
  CHECK(shape::lean_degrees(leaning_tree(50, 10)) == Approx(50).margin(1.0));
}

TEST_CASE("trunk lean: a scan of a thick tilted trunk with a low branch measures its tilt",
          "[shape]") {
  // The trunk stands on flat ground: it starts below z = 0 and the points below are cut off,
  // as a scan of a real tree sees it (a cut across the axis would put more of the lowest 5 %
  // on the downhill side and move b0 there).
  const Vec3 dir = tilted(20, 30);
  std::vector<Vec3> points;
  for (const Vec3& p : bark(dir * -1.0, dir * 10.0, 0.35, 220, 24)) {
    if (p.z >= 0) points.push_back(p);
  }
  // A low side branch, thinner, sticking out horizontally at 0.2 of the height.
  const std::vector<Vec3> branch = bark(dir * 2.0, dir * 2.0 + Vec3{0, -3, 0.3}, 0.1, 60, 10);
  points.insert(points.end(), branch.begin(), branch.end());
  const PointCloud scan = cloud_of(points, {5e5, 4e6, 100});  // UTM-like offset
  CHECK(shape::lean_degrees(scan) == Approx(20).margin(1.0));
  // Thin trunk, its skeleton: the same.
  Skeleton s;
  chain(s, {0, 0, 0}, dir * 10.0, 20);
  CHECK(shape::lean_degrees(s) == Approx(20).margin(0.5));
}

TEST_CASE("trunk lean: undefined without height", "[shape]") {
  CHECK(std::isnan(shape::trunk_lean_degrees({})));
  CHECK(std::isnan(shape::trunk_lean_degrees({{0, 0, 1}, {1, 0, 1}})));
}

TEST_CASE("trunk lean: a skeleton is measured from its root, whips below it do not count",
          "[shape]") {
  // A vertical trunk of 10 with whips from 3 hanging 1.5 below its root, all on one side: from
  // the lowest 5 % (the points rule) the start lies among the whip tips.
  Skeleton s;
  const std::uint32_t low = chain(s, {0, 0, 0}, {0, 0, 3}, 12);
  chain(s, {0, 0, 3}, {0, 0, 10}, 20, low);
  for (int k = 0; k < 6; ++k) {
    const Vec3 out{2.0 + 0.2 * k, 0.3 * (k - 3), -1.5};
    chain(s, {0, 0, 3}, out, 10, low);
  }
  // (1.5: where the whips leave the trunk they pass within the window.)
  CHECK(shape::lean_degrees(s) == Approx(0).margin(2.0));
  // The same samples without the root: the points rule, thrown off by the whips.
  std::vector<Vec3> points;
  for (const SkeletonNode& n : s.nodes) points.push_back(n.position);
  CHECK(shape::trunk_lean_degrees(points) > 5);
  CHECK(shape::trunk_lean_degrees(points, Vec3{0, 0, 0}) == Approx(0).margin(2.0));
  // A leaning tree keeps its lean from the root.
  CHECK(shape::lean_degrees(leaning_tree(20, 30)) == Approx(20).margin(0.5));
}
