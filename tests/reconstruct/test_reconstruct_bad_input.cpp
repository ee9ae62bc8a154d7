// reconstruct() on input that holds no tree: clear errors or empty results, never a crash.
#include <catch2/catch.hpp>

#include <limits>

#include "core/rng.h"
#include "reconstruct/reconstruct.h"

using namespace ramus;

TEST_CASE("reconstruct bad input: an empty cloud is an error", "[reconstruct]") {
  PointCloud cloud;
  CHECK_THROWS_AS(reconstruct(cloud), ReconstructError);
}

TEST_CASE("reconstruct bad input: a single point is an error", "[reconstruct]") {
  PointCloud cloud;
  cloud.positions.push_back({1, 2, 3});
  CHECK_THROWS_WITH(reconstruct(cloud), Catch::Contains("finite coordinates"));
}

TEST_CASE("reconstruct bad input: NaN coordinates are dropped and counted", "[reconstruct]") {
  PointCloud cloud;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cloud.positions = {{nan, 0, 0}, {0, nan, 1}, {0, 0, nan}};
  CHECK_THROWS_AS(reconstruct(cloud), ReconstructError);
  Rng rng(1);
  for (int i = 0; i < 500; ++i) {
    cloud.positions.push_back(Vec3f(float(rng.uniform(-1, 1)), float(rng.uniform(-1, 1)), 0.f));
  }
  const ReconstructResult r = reconstruct(cloud);
  CHECK(r.counts.dropped_points == 3);
  CHECK(r.trees.empty());  // a flat patch is all terrain
  CHECK_FALSE(r.notes.empty());
}

TEST_CASE("reconstruct bad input: duplicate points give an empty result", "[reconstruct]") {
  PointCloud cloud;
  cloud.positions.assign(1000, Vec3f{5, 5, 5});
  const ReconstructResult r = reconstruct(cloud);
  CHECK(r.trees.empty());
  CHECK_FALSE(r.notes.empty());
}

TEST_CASE("reconstruct bad input: coplanar points give an empty result", "[reconstruct]") {
  Rng rng(2);
  PointCloud flat, tilted;
  for (int i = 0; i < 5000; ++i) {
    const double u = rng.uniform(0, 10), v = rng.uniform(0, 10);
    flat.positions.push_back(Vec3f(float(u), float(v), 0.f));
    tilted.positions.push_back(Vec3f(float(u), float(v), float(0.3 * u)));
  }
  CHECK(reconstruct(flat).trees.empty());
  CHECK(reconstruct(tilted).trees.empty());
}

TEST_CASE("reconstruct bad input: a building without trees gives no tree", "[reconstruct]") {
  // Four walls 12 m long and 6 m high on a ground plane.
  Rng rng(3);
  PointCloud cloud;
  for (int i = 0; i < 40000; ++i) {
    const double s = rng.uniform(0, 12), h = rng.uniform(0, 6);
    const int wall = int(rng.below(5));
    Vec3f p;
    if (wall == 0) p = Vec3f(float(s), 0.f, float(h));
    if (wall == 1) p = Vec3f(float(s), 12.f, float(h));
    if (wall == 2) p = Vec3f(0.f, float(s), float(h));
    if (wall == 3) p = Vec3f(12.f, float(s), float(h));
    if (wall == 4) p = Vec3f(float(rng.uniform(-5, 17)), float(rng.uniform(-5, 17)), 0.f);
    cloud.positions.push_back(p);
  }
  const ReconstructResult r = reconstruct(cloud);
  CHECK(r.trees.empty());
  REQUIRE_FALSE(r.notes.empty());
  CHECK(r.notes.back().find("no tree base") != std::string::npos);
}
