// reconstruct() on input that holds no tree: clear errors or empty results, never a crash.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "core/rng.h"
#include "reconstruct/reconstruct.h"
#include "tests/reconstruct/reconstruct_fixtures.h"

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

// Issue 19, point 6: a fence, points on one line and far outliers.
TEST_CASE("reconstruct bad input: a fence (a long thin wall) gives no tree", "[reconstruct]") {
  Rng rng(4);
  PointCloud cloud;
  // A fence 30 m long, 1.5 m high, 5 cm thick, on a ground plane: 2000 points per square metre
  // of its face, as a terrestrial scan from a few metres away.
  for (int i = 0; i < 120000; ++i) {
    if (i % 4 == 0) {
      cloud.positions.push_back(
          Vec3f(float(rng.uniform(-2, 32)), float(rng.uniform(-3, 3)), float(rng.normal(0, 0.01))));
    } else {
      cloud.positions.push_back(Vec3f(float(rng.uniform(0, 30)), float(rng.uniform(0, 0.05)),
                                      float(rng.uniform(0, 1.5))));
    }
  }
  const ReconstructResult r = reconstruct(cloud);
  INFO((r.notes.empty() ? std::string() : r.notes.back()) << "; trees " << r.trees.size());
  CHECK(r.trees.empty());
  CHECK_FALSE(r.notes.empty());
}

TEST_CASE("reconstruct bad input: points on one line give a clear result, no crash",
          "[reconstruct]") {
  PointCloud vertical, horizontal;
  for (int i = 0; i < 2000; ++i) {
    vertical.positions.push_back(Vec3f(1.f, 2.f, 0.005f * float(i)));
    horizontal.positions.push_back(Vec3f(0.005f * float(i), 2.f, 0.f));
  }
  // A vertical line is a pole: at most one tree, a straight chain, finite everywhere.
  const ReconstructResult v = reconstruct(vertical);
  CHECK(v.trees.size() <= 1);
  for (const Skeleton& s : v.trees) CHECK(s.validate().empty());
  if (v.trees.empty()) CHECK_FALSE(v.notes.empty());
  // A horizontal line has no height: no tree, and a note saying why.
  const ReconstructResult h = reconstruct(horizontal);
  CHECK(h.trees.empty());
  CHECK_FALSE(h.notes.empty());
}

TEST_CASE("reconstruct bad input: outliers kilometres away are ignored", "[reconstruct]") {
  Rng rng(5);
  PointCloud clean;
  test::sample_bark(test::synthetic_tree(3, {0, 0, 0}), 1500, 0.003, rng, clean);
  PointCloud noisy = clean;
  noisy.positions.push_back(Vec3f(3000.f, 0.f, 5.f));
  noisy.positions.push_back(Vec3f(-2500.f, 1800.f, 40.f));
  noisy.positions.push_back(Vec3f(0.f, 0.f, 2200.f));
  const ReconstructResult a = reconstruct(clean), b = reconstruct(noisy);
  REQUIRE(a.trees.size() == 1);
  INFO((b.notes.empty() ? std::string() : b.notes.back()));
  REQUIRE(b.trees.size() == 1);
  CHECK(b.trees[0].validate().empty());
  // The tree is the same tree: its length within 10%, its top within 10 cm.
  CHECK(b.trees[0].total_length() == Approx(a.trees[0].total_length()).epsilon(0.1));
  Vec3 alo, ahi, blo, bhi;
  a.trees[0].bounds(alo, ahi);
  b.trees[0].bounds(blo, bhi);
  CHECK(std::abs(ahi.z - bhi.z) < 0.1);
  CHECK(b.counts.outlier_points == 3);
  CHECK(b.notes.front().find("outliers") != std::string::npos);
}
