// The accuracy harness: trees with known skeletons -> simulated scans (one and three stations,
// with range noise) -> reconstruct() -> comparison with the truth. The thresholds below are the
// levels the implementation reaches today (docs/reconstruction.md lists the measured values);
// they guard against regressions, and the grammar cases below state their margins.
#include <catch2/catch.hpp>
#include <string>

#include "backends/scanner/harness.h"
#include "compiler/grow.h"
#include "tests/compiler/reconstruct_fixtures.h"

using namespace ramus;

TEST_CASE("reconstruct accuracy: synthetic tree scanned from three stations", "[accuracy]") {
  const Skeleton truth = test::synthetic_tree(7, {0, 0, 0});
  scanner::HarnessCase c;
  c.stations = 3;
  c.noise = 0.003;
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
  c.noise = 0.003;
  const scanner::HarnessResult r = scanner::run_harness(truth, c);
  const SkeletonComparison& a = r.at_radius;
  INFO("points " << r.points << " precision " << a.precision << " recall " << a.recall << " length "
                 << a.length_ratio);
  REQUIRE(r.trees == 1);
  CHECK(a.precision >= 0.8);
  CHECK(a.recall >= 0.5);
}

// The targets (precision within 2 x radius >= 0.9, total length within 20%) on the
// bundled grammar trees scanned from three stations, with the fine settings of
// docs/reconstruction.md (voxel of one median point spacing, 10 contraction steps, 2 rounds; not
// the defaults, which leave 0.88 / 0.77 / 0.61 and length 0.60 / 0.52 / 0.97). Measured: broadleaf
// 0.988 / 0.979, conifer 0.979 / 0.891, weeping 0.920 / 1.140. Deterministic (fixed grammar seed,
// scanner seed and reconstruction); the checks are the targets themselves, so the margins are the
// distances to them: precision 0.088 / 0.079 / 0.020, length 0.179 / 0.091 / 0.060. The
// fixed-distance recall (1% of the height) is a regression guard: measured 0.94 / 0.88 / 0.99.
namespace {

ReconstructOptions fine_options() {
  ReconstructOptions o;
  o.voxel_spacings = 1.0;
  o.voxel_height_floor = 1.0 / 1000;
  o.contraction_steps = 10;
  o.max_iterations = 2;
  return o;
}

scanner::HarnessResult three_station_scan(const char* grammar, const ReconstructOptions& o) {
  SourceManager sources;
  DiagnosticSink diags;
  const Skeleton truth =
      grow_file(std::string(RAMUS_SOURCE_DIR "/examples/trees/") + grammar, {}, sources, diags);
  REQUIRE(truth.size() > 10);
  scanner::HarnessCase c;
  c.stations = 3;
  return scanner::run_harness(truth, c, o);
}

void check_targets(const scanner::HarnessResult& r, double min_recall_distance) {
  const SkeletonComparison& a = r.at_radius;
  INFO("points " << r.points << " trees " << r.trees << " precision " << a.precision
                 << " precision(1%h) " << a.precision_distance << " recall(1%h) "
                 << a.recall_distance << " length " << a.length_ratio);
  REQUIRE(r.trees == 1);
  CHECK(a.precision >= 0.9);
  CHECK(a.length_ratio > 0.8);
  CHECK(a.length_ratio < 1.2);
  CHECK(a.recall_distance >= min_recall_distance);
}

}  // namespace

TEST_CASE("reconstruct accuracy: bundled broadleaf grammar, three stations, fine voxel",
          "[accuracy]") {
  check_targets(three_station_scan("broadleaf.ramus", fine_options()), 0.9);
}

TEST_CASE("reconstruct accuracy: bundled conifer grammar, three stations, fine voxel",
          "[accuracy]") {
  check_targets(three_station_scan("conifer.ramus", fine_options()), 0.8);
}

TEST_CASE("reconstruct accuracy: bundled weeping grammar, three stations, fine voxel",
          "[accuracy]") {
  check_targets(three_station_scan("weeping.ramus", fine_options()), 0.9);
}

// Weeping from three stations with the default (automatic, 2.5-spacing) voxel: length 0.967
// (within 20%), precision within 2 x radius 0.610 (whips of 1.3 cm radius; the 2 x radius target
// is not met with the defaults, see docs/reconstruction.md), precision within 1% of the height
// 0.927. Regression guards.
TEST_CASE("reconstruct accuracy: bundled weeping grammar, three stations, defaults", "[accuracy]") {
  const scanner::HarnessResult r = three_station_scan("weeping.ramus", {});
  const SkeletonComparison& a = r.at_radius;
  INFO("points " << r.points << " precision " << a.precision << " length " << a.length_ratio);
  REQUIRE(r.trees == 1);
  CHECK(a.length_ratio > 0.8);
  CHECK(a.length_ratio < 1.2);
  CHECK(a.precision >= 0.55);
  CHECK(a.precision_distance >= 0.9);
}
