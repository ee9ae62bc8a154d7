// Stray points (reconstruct/bsg/stray_points.h): points alone in the air are dropped, the points
// of a surface or of a thin twig sampled along its length are kept, points already left out
// neither count as neighbours nor are counted again, and the reach may follow the median spacing
// that the same search measures. Runs of a few points alone (a cluster smaller than the rule's)
// go too, and the clusters are those of a brute-force search on random clouds.
#include <catch2/catch.hpp>
#include <numeric>

#include "core/rng.h"
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
  CHECK(bsg::drop_stray_points(p, keep, 0.04, {1, 0}) == 0);
  // Two asked: the twig's inner points have two (3 cm either side); its ends and the pair go.
  CHECK(bsg::drop_stray_points(p, keep, 0.04, {2, 0}) == 4);
  CHECK(keep[0] == 0);
  CHECK(keep[11] == 0);
  for (int k = 1; k < 11; ++k) CHECK(keep[std::size_t(k)] == 1);
  CHECK(keep[12] == 0);
  CHECK(keep[13] == 0);
  // A wider reach keeps the whole twig.
  std::fill(keep.begin(), keep.end(), 1);
  CHECK(bsg::drop_stray_points(p, keep, 0.07, {2, 0}) == 2);
  for (int k = 0; k < 12; ++k) CHECK(keep[std::size_t(k)] == 1);
}

TEST_CASE("stray points: points already left out do not count", "[reconstruct]") {
  std::vector<Eigen::Vector3d> p{{0, 0, 0}, {0.01, 0, 0}, {0.02, 0, 0}};
  std::vector<std::uint8_t> keep{1, 1, 0};
  // Two points kept, each with one other within reach: both stray when two are asked, and the
  // third, already out, is not counted among the dropped.
  CHECK(bsg::drop_stray_points(p, keep, 0.05, {2, 0}) == 0);  // too few points to judge
  p.emplace_back(5, 5, 5);
  keep.push_back(1);
  CHECK(bsg::drop_stray_points(p, keep, 0.05, {2, 0}) == 3);
  CHECK(keep == std::vector<std::uint8_t>{0, 0, 0, 0});
  // Nothing to do for a reach of zero or no neighbours asked.
  keep.assign(4, 1);
  CHECK(bsg::drop_stray_points(p, keep, 0.0, {2, 0}) == 0);
  CHECK(bsg::drop_stray_points(p, keep, 0.05, {0, 0}) == 0);
}

TEST_CASE("stray points: a run of three alone in the air goes, a line of eight stays",
          "[reconstruct]") {
  std::vector<Eigen::Vector3d> p = patch();
  const std::size_t surface = p.size();
  // Three points 1.5 cm apart (one scan line's mixed pixels at a twig edge), 50 cm above.
  for (int k = 0; k < 3; ++k) p.emplace_back(0.1, 0.1, 0.5 + 0.015 * k);
  // Eight points 1.5 cm apart on a line, 50 cm to the side: a cluster of eight.
  for (int k = 0; k < 8; ++k) p.emplace_back(0.7, 0.0, 0.015 * k);
  std::vector<std::uint8_t> keep(p.size(), 1);
  // Each point of the run has two others within 4 cm: the neighbour test alone keeps it.
  CHECK(bsg::drop_stray_points(p, keep, 0.04, {2, 0}) == 0);
  CHECK(bsg::drop_stray_points(p, keep, 0.04, {2, 5}) == 3);  // clusters below five
  for (std::size_t i = 0; i < surface; ++i) CHECK(keep[i] == 1);
  for (std::size_t i = surface; i < surface + 3; ++i) CHECK(keep[i] == 0);
  for (std::size_t i = surface + 3; i < p.size(); ++i) CHECK(keep[i] == 1);
  // Nine asked: the line of eight goes too.
  std::fill(keep.begin(), keep.end(), 1);
  CHECK(bsg::drop_stray_points(p, keep, 0.04, {2, 9}) == 11);
  // A run within reach of the surface is part of its cluster and stays.
  p.emplace_back(0.1, 0.1, 0.035);
  p.emplace_back(0.1, 0.1, 0.07);
  keep.assign(p.size(), 1);
  CHECK(bsg::drop_stray_points(p, keep, 0.04, {1, 8}) == 3);
  CHECK(keep[p.size() - 1] == 1);
  CHECK(keep[p.size() - 2] == 1);
}

TEST_CASE("stray points: no cluster is dropped for its size when none is large enough",
          "[reconstruct]") {
  std::vector<Eigen::Vector3d> p;
  for (int k = 0; k < 5; ++k) p.emplace_back(0.015 * k, 0.0, 0.0);
  for (int k = 0; k < 4; ++k) p.emplace_back(2.0, 0.015 * k, 0.0);
  std::vector<std::uint8_t> keep(p.size(), 1);
  // Every point has at least one other within reach; both clusters are below eight.
  CHECK(bsg::drop_stray_points(p, keep, 0.02, {1, 8}) == 0);
  // Five asked: the cluster of four goes, the five stay.
  CHECK(bsg::drop_stray_points(p, keep, 0.02, {1, 5}) == 4);
  for (int k = 0; k < 5; ++k) CHECK(keep[std::size_t(k)] == 1);
}

TEST_CASE("stray points: the clusters are those of a brute-force search", "[reconstruct]") {
  for (std::uint64_t seed = 0; seed < 40; ++seed) {
    Rng rng = Rng::stream(seed, 19);
    // Clumps of 1-12 points of 2 cm spread, scattered in a 1 m cube, and points already out.
    std::vector<Eigen::Vector3d> p;
    while (p.size() < 300) {
      const Eigen::Vector3d c(rng.uniform01(), rng.uniform01(), rng.uniform01());
      const int n = 1 + int(rng.uniform01() * 12);
      for (int k = 0; k < n; ++k)
        p.push_back(c + 0.02 * Eigen::Vector3d(rng.uniform01(), rng.uniform01(), rng.uniform01()));
    }
    std::vector<std::uint8_t> keep(p.size());
    for (auto& k : keep) k = rng.uniform01() < 0.95;
    const double reach = 0.01 + 0.03 * rng.uniform01();
    const bsg::StrayRule rule{int(rng.uniform01() * 3), std::size_t(2 + rng.uniform01() * 10)};
    // Brute force: others within reach, and components by repeated relabelling.
    std::vector<std::size_t> label(p.size()), others(p.size(), 0);
    std::iota(label.begin(), label.end(), std::size_t(0));
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t j = 0; j < p.size(); ++j) {
          if (!keep[i] || !keep[j] || (p[i] - p[j]).squaredNorm() >= reach * reach) continue;
          if (label[j] < label[i]) label[i] = label[j], changed = true;
        }
    }
    std::vector<std::size_t> size(p.size(), 0);
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (!keep[i]) continue;
      ++size[label[i]];
      for (std::size_t j = 0; j < p.size(); ++j)
        others[i] += j != i && keep[j] && (p[i] - p[j]).squaredNorm() < reach * reach;
    }
    bool any_large = false;
    for (std::size_t i = 0; i < p.size(); ++i)
      any_large |= keep[i] && size[label[i]] >= rule.min_cluster;
    std::vector<std::uint8_t> expected = keep;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (!keep[i]) continue;
      if (others[i] < std::size_t(rule.min_neighbours) ||
          (any_large && size[label[i]] < rule.min_cluster))
        expected[i] = 0;
    }
    std::vector<std::uint8_t> got = keep;
    bsg::drop_stray_points(p, got, reach, rule);
    INFO("seed " << seed);
    CHECK(got == expected);
  }
}

TEST_CASE("stray points: the pipelines' two passes share the first one's reach", "[reconstruct]") {
  std::vector<Eigen::Vector3d> p = patch();
  const std::size_t surface = p.size();
  for (int k = 0; k < 5; ++k) p.emplace_back(0.04 * k, 0.1, 0.2 + 0.1 * k);  // alone
  for (int k = 0; k < 3; ++k) p.emplace_back(0.1, 0.1, 0.8 + 0.01 * k);      // a run of three
  std::vector<std::uint8_t> keep(p.size(), 1);
  bsg::StrayPasses passes({2, 5});
  passes.clusters(p, keep);  // before alone(): no reach yet, nothing to do
  CHECK(passes.dropped() == 0);
  passes.alone(p, keep, [](double spacing) { return 4 * spacing; });
  CHECK(passes.dropped() == 5);
  passes.clusters(p, keep);
  CHECK(passes.dropped() == 8);
  for (std::size_t i = 0; i < surface; ++i) CHECK(keep[i] == 1);
  CHECK(passes.note("voxels") ==
        "ignored 8 stray point(s): fewer than two others within four voxels, or in a cluster of "
        "fewer than 5 points");
  CHECK(bsg::StrayPasses({2, 1}).note("point spacings") ==
        "ignored 0 stray point(s): fewer than two others within four point spacings");
}
