// The k-d tree's slab query (reconstruct/bsg/kdtree.h): PointIndex::within_slab must give the
// points of within() that lie in the slab, in within()'s order, because the cross-sections'
// thinning, sums and random triples depend on that order (the reconstructions are byte for byte
// those of the ball query). The capped count is the ball query's size, up to the cap.
#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cmath>

#include "core/rng.h"
#include "reconstruct/bsg/kdtree.h"

using namespace ramus;
using ramus::bsg::PointIndex;

namespace {

// Points on the bark of a leaning trunk and two limbs, with noise: the shape the slabs cut.
std::vector<Eigen::Vector3d> bark(std::uint64_t seed, int n) {
  Rng rng(seed);
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i < n; ++i) {
    const int part = int(rng.below(3));
    const double t = rng.uniform(0, 1), a = rng.uniform(0, 2 * M_PI);
    const double r = (part == 0 ? 0.3 : 0.08) + rng.normal(0, 0.003);
    const Eigen::Vector3d base = part == 0 ? Eigen::Vector3d(0, 0, 0) : Eigen::Vector3d(0, 0, 3);
    const Eigen::Vector3d dir = part == 0   ? Eigen::Vector3d(0.1, 0, 1).normalized()
                                : part == 1 ? Eigen::Vector3d(1, 0, 1).normalized()
                                            : Eigen::Vector3d(-1, 0.5, 0.8).normalized();
    const double len = part == 0 ? 6.0 : 2.0;
    const Eigen::Vector3d e1 = dir.cross(Eigen::Vector3d::UnitY()).normalized(), e2 = dir.cross(e1);
    pts.push_back(base + t * len * dir + r * (std::cos(a) * e1 + std::sin(a) * e2));
  }
  return pts;
}

// The caller's exact test (centre_line.cpp's fit_slab): |(p - q) . d| <= half.
std::vector<std::uint32_t> in_slab(const std::vector<std::uint32_t>& ids,
                                   const std::vector<Eigen::Vector3d>& pts,
                                   const Eigen::Vector3d& q, const Eigen::Vector3d& d,
                                   double half) {
  std::vector<std::uint32_t> out;
  for (std::uint32_t i : ids) {
    if (std::abs((pts[i] - q).dot(d)) <= half) out.push_back(i);
  }
  return out;
}

}  // namespace

TEST_CASE("within_slab gives the slab's points of the ball query in its order", "[reconstruct]") {
  const std::vector<Eigen::Vector3d> pts = bark(11, 20000);
  // The whole cloud, and a subset by index (the index then reports the original indices).
  std::vector<std::uint32_t> subset;
  for (std::uint32_t i = 0; i < pts.size(); i += 3) subset.push_back(i);
  for (const bool use_subset : {false, true}) {
    const PointIndex index(pts, use_subset ? subset : std::vector<std::uint32_t>{});
    Rng rng(5);
    std::size_t found = 0, ball = 0;
    for (int k = 0; k < 300; ++k) {
      // Queries on the bark and beside it, slabs across and along the branches.
      const Eigen::Vector3d q =
          pts[rng.below(pts.size())] + Eigen::Vector3d(rng.normal(0, 0.1), rng.normal(0, 0.1), 0);
      Eigen::Vector3d d(rng.normal(0, 1), rng.normal(0, 1), rng.normal(0, 1));
      d.normalize();
      const double half = rng.uniform(0.005, 0.2), radius = rng.uniform(0.05, 1.5);
      std::vector<std::uint32_t> all, slab;
      index.within(q, radius, all);
      index.within_slab(q, radius, d, half, slab);
      const std::vector<std::uint32_t> expected = in_slab(all, pts, q, d, half);
      // Points near the slab's faces may come too (widened bounds): the exact test of the
      // caller must then give the same sequence.
      REQUIRE(in_slab(slab, pts, q, d, half) == expected);
      REQUIRE(slab.size() <= all.size());
      found += expected.size(), ball += all.size();
    }
    // The test means something: the slabs hold points, and fewer than the balls.
    CHECK(found > 1000);
    CHECK(found < ball);
  }
}

TEST_CASE("within_slab on an empty index or a zero radius finds nothing", "[reconstruct]") {
  const std::vector<Eigen::Vector3d> none;
  const PointIndex empty(none);
  std::vector<std::uint32_t> out;
  empty.within_slab(Eigen::Vector3d::Zero(), 1.0, Eigen::Vector3d::UnitZ(), 0.1, out);
  CHECK(out.empty());
  const std::vector<Eigen::Vector3d> one = {Eigen::Vector3d(0, 0, 0)};
  const PointIndex single(one);
  single.within_slab(Eigen::Vector3d::Zero(), 0.0, Eigen::Vector3d::UnitZ(), 0.1, out);
  CHECK(out.empty());
  single.within_slab(Eigen::Vector3d(0, 0, 0.05), 1.0, Eigen::Vector3d::UnitZ(), 0.1, out);
  CHECK(out == std::vector<std::uint32_t>{0});
}

TEST_CASE("count_within is the ball query's size up to the cap", "[reconstruct]") {
  const std::vector<Eigen::Vector3d> pts = bark(12, 5000);
  const PointIndex index(pts);
  Rng rng(6);
  std::size_t capped = 0, below = 0;
  for (int k = 0; k < 500; ++k) {
    const Eigen::Vector3d q =
        pts[rng.below(pts.size())] + Eigen::Vector3d(rng.normal(0, 0.05), rng.normal(0, 0.05), 0);
    const double radius = rng.uniform(0.005, 0.1);
    const std::size_t cap = 1 + rng.below(12);
    std::vector<std::uint32_t> all;
    index.within(q, radius, all);
    REQUIRE(index.count_within(q, radius, cap) == std::min(all.size(), cap));
    (all.size() >= cap ? capped : below) += 1;
  }
  // Both sides of the cap are met.
  CHECK(capped > 50);
  CHECK(below > 50);
  const std::vector<Eigen::Vector3d> none;
  CHECK(PointIndex(none).count_within(Eigen::Vector3d::Zero(), 1.0, 5) == 0);
  CHECK(index.count_within(pts[0], 0.0, 5) == 0);
  CHECK(index.count_within(pts[0], 1.0, 0) == 0);
}
