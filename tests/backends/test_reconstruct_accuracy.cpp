// The accuracy harness: trees with known skeletons -> simulated scans (one and three stations,
// with range noise) -> reconstruct() -> comparison with the truth. The thresholds below are the
// levels the implementation reaches today (docs/reconstruction.md lists the measured values);
// they guard against regressions. The targets are stricter for the grammar trees.
#include <catch2/catch.hpp>

#include "backends/scanner/harness.h"
#include "compiler/grow.h"
#include "tests/compiler/reconstruct_fixtures.h"

using namespace ramus;

TEST_CASE("reconstruct accuracy: synthetic tree scanned from three stations", "[accuracy]") {
  const Skeleton truth = test::synthetic_tree(7, {0, 0, 0});
  scanner::HarnessCase c;
  c.stations = 3;
  c.noise = 0.0005;
  c.density = 3000;
  const scanner::HarnessResult r = scanner::run_harness(truth, c);
  const SkeletonComparison& a = r.at_radius;
  INFO("points " << r.points << " precision " << a.precision << " recall " << a.recall << " length "
                 << a.length_ratio << " chamfer " << a.chamfer);
  REQUIRE(r.trees == 1);
  CHECK(a.precision >= 0.9);
  CHECK(a.recall >= 0.7);
  CHECK(a.length_ratio > 0.7);
  CHECK(a.length_ratio < 1.5);
}

TEST_CASE("reconstruct accuracy: synthetic tree scanned from one station", "[accuracy]") {
  const Skeleton truth = test::synthetic_tree(7, {0, 0, 0});
  scanner::HarnessCase c;
  c.stations = 1;
  c.noise = 0.0005;
  const scanner::HarnessResult r = scanner::run_harness(truth, c);
  const SkeletonComparison& a = r.at_radius;
  INFO("points " << r.points << " precision " << a.precision << " recall " << a.recall << " length "
                 << a.length_ratio);
  REQUIRE(r.trees == 1);
  CHECK(a.precision >= 0.8);
  CHECK(a.recall >= 0.5);
}

TEST_CASE("reconstruct accuracy: bundled broadleaf grammar, three stations", "[accuracy]") {
  SourceManager sources;
  DiagnosticSink diags;
  const Skeleton truth =
      grow_file(RAMUS_SOURCE_DIR "/examples/trees/broadleaf.ramus", {}, sources, diags);
  REQUIRE(truth.size() > 10);
  scanner::HarnessCase c;
  c.stations = 3;
  const scanner::HarnessResult r = scanner::run_harness(truth, c);
  const SkeletonComparison& a = r.at_radius;
  INFO("points " << r.points << " trees " << r.trees << " precision " << a.precision
                 << " precision(1%h) " << a.precision_distance << " recall(1%h) "
                 << a.recall_distance << " length " << a.length_ratio);
  REQUIRE(r.trees >= 1);
  CHECK(a.precision_distance >= 0.6);
  CHECK(a.recall_distance >= 0.4);
}
