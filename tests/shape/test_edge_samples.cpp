// Edge samples (infer/shape/edge_samples.h): each node on an edge once, segments cut into
// equal intervals no longer than the step.
#include <catch2/catch.hpp>

#include "infer/shape/edge_samples.h"
#include "infer/shape/shape_error.h"
#include "shape_fixtures.h"

using namespace ramus;
using namespace shape_test;

TEST_CASE("edge samples: every node once, intervals no longer than the step", "[shape]") {
  Skeleton s;
  const std::uint32_t fork = chain(s, {0, 0, 0}, {0, 0, 1}, 1);  // 2 nodes
  chain(s, {0, 0, 1}, {0.3, 0, 1}, 1, fork);                     // 0.3 at step 0.25: 2 parts
  chain(s, {0, 0, 1}, {0, 0, 2}, 1, fork);                       // 1.0: 4 parts
  SkeletonNode lonely;                                           // a root without segment
  lonely.position = {9, 9, 9};
  s.add(lonely);
  const std::vector<Vec3> v = shape::sample_edges(s, 0.25);
  // Root 1 + trunk 4 + branch 2 + leader 4.
  CHECK(v.size() == 11);
  CHECK(v.front() == Vec3{0, 0, 0});
  for (const Vec3& p : v) CHECK(p.x < 5);  // the lonely root is on no edge
  double lo = 0, hi = 0;
  REQUIRE(shape::segment_z_range(s, lo, hi));
  CHECK(lo == 0.0);
  CHECK(hi == 2.0);
  CHECK_FALSE(shape::segment_z_range(Skeleton{}, lo, hi));
  CHECK_THROWS_AS(shape::sample_edges(s, 0), shape::ShapeError);
  CHECK_THROWS_AS(shape::sample_edges(s, 1e-9, 1000), shape::ShapeError);
}
