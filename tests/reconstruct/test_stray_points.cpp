// Stray points (reconstruct/bsg/stray_points.h): points alone in the air are dropped, the points
// of a surface or of a thin twig sampled along its length are kept, points already left out
// neither count as neighbours nor are counted again, and the reach may follow the median spacing
// that the same search measures.
#include <catch2/catch.hpp>

#include "reconstruct/bsg/kdtree.h"
#include "reconstruct/bsg/stray_points.h"

using namespace ramus;

namespace {

// A 20 x 20 cm patch of points 1 cm apart at z = 0.
std::vector<Eigen::Vector3d> patch() {
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) p.emplace_back(0.01 * i, 0.01 * j, 0.0);
  return p;
}

}  // namespace

TEST_CASE("stray points: points alone in the air go, a surface stays", "[reconstruct]") {
  std::vector<Eigen::Vector3d> p = patch();
  const std::size_t surface = p.size();
  for (int k = 0; k < 5; ++k) p.emplace_back(0.04 * k, 0.1, 0.2 + 0.1 * k);  // 10 cm apart
  std::vector<std::uint8_t> keep(p.size(), 1);
  CHECK(bsg::drop_stray_points(p, keep, 0.04) == 5);
  for (std::size_t i = 0; i < surface; ++i) CHECK(keep[i] == 1);
  for (std::size_t i = surface; i < p.size(); ++i) CHECK(keep[i] == 0);
}

TEST_CASE("stray points: the reach can follow the median spacing the same search measures",
          "[reconstruct]") {
  std::vector<Eigen::Vector3d> p = patch();
  const std::size_t surface = p.size();
  for (int k = 0; k < 5; ++k) p.emplace_back(0.04 * k, 0.1, 0.2 + 0.1 * k);
  std::vector<std::uint8_t> keep(p.size(), 1);
  double measured = 0;
  const std::size_t dropped = bsg::drop_stray_points(p, keep, [&](double spacing) {
    measured = spacing;
    return 4 * spacing;
  });
  CHECK(measured == Approx(0.01));  // the patch's spacing; the five strays do not move the median
  CHECK(dropped == 5);
  for (std::size_t i = 0; i < surface; ++i) CHECK(keep[i] == 1);
  // The same as median_spacing (kdtree.h) over the same points.
  std::vector<std::uint32_t> ids(p.size());
  for (std::uint32_t i = 0; i < ids.size(); ++i) ids[i] = i;
  CHECK(measured == bsg::median_spacing(p, ids, false));
}

TEST_CASE("stray points: a twig sampled along its length stays, a pair alone goes",
          "[reconstruct]") {
  std::vector<Eigen::Vector3d> p;
  for (int k = 0; k < 12; ++k) p.emplace_back(0.0, 0.0, 0.03 * k);  // 3 cm apart, 4 cm reach
  p.emplace_back(1.0, 0.0, 0.0);
  p.emplace_back(1.0, 0.02, 0.0);  // two points 2 cm apart, 1 m from the twig
  std::vector<std::uint8_t> keep(p.size(), 1);
  // Every twig point has at least one other within 4 cm, the end points one only: with one
  // neighbour asked they stay, the pair too.
  CHECK(bsg::drop_stray_points(p, keep, 0.04, 1) == 0);
  // Two asked: the twig's inner points have two (3 cm either side); its ends and the pair go.
  CHECK(bsg::drop_stray_points(p, keep, 0.04, 2) == 4);
  CHECK(keep[0] == 0);
  CHECK(keep[11] == 0);
  for (int k = 1; k < 11; ++k) CHECK(keep[std::size_t(k)] == 1);
  CHECK(keep[12] == 0);
  CHECK(keep[13] == 0);
  // A wider reach keeps the whole twig.
  std::fill(keep.begin(), keep.end(), 1);
  CHECK(bsg::drop_stray_points(p, keep, 0.07, 2) == 2);
  for (int k = 0; k < 12; ++k) CHECK(keep[std::size_t(k)] == 1);
}

TEST_CASE("stray points: points already left out do not count", "[reconstruct]") {
  std::vector<Eigen::Vector3d> p{{0, 0, 0}, {0.01, 0, 0}, {0.02, 0, 0}};
  std::vector<std::uint8_t> keep{1, 1, 0};
  // Two points kept, each with one other within reach: both stray when two are asked, and the
  // third, already out, is not counted among the dropped.
  CHECK(bsg::drop_stray_points(p, keep, 0.05, 2) == 0);  // too few points to judge
  p.emplace_back(5, 5, 5);
  keep.push_back(1);
  CHECK(bsg::drop_stray_points(p, keep, 0.05, 2) == 3);
  CHECK(keep == std::vector<std::uint8_t>{0, 0, 0, 0});
  // Nothing to do for a reach of zero or no neighbours asked.
  keep.assign(4, 1);
  CHECK(bsg::drop_stray_points(p, keep, 0.0, 2) == 0);
  CHECK(bsg::drop_stray_points(p, keep, 0.05, 0) == 0);
}
