// The accuracy harness: trees with known skeletons -> simulated scans (one and three stations,
// with range noise) -> reconstruct() -> comparison with the truth. The thresholds below are the
// issue's targets where the implementation meets them and regression guards elsewhere
// (docs/reconstruction.md lists the measured values); each case states its margins.
#include <catch2/catch.hpp>
#include <string>

#include "compiler/grow.h"
#include "tests/reconstruct/reconstruct_fixtures.h"
#include "tests/support/harness.h"

using namespace ramus;

// A six-metre tree with a 15 cm trunk and 25 branches 4-8 cm thick: at the default voxel of one
// point spacing (1.8 cm) its branches are 5-10 voxels thick. Without the thickness-adaptive axis
// projection the neighbour-mean contraction did not reach their axes and the bark kept parallel
// paths: length 2.56 x the truth, 177 tips for 25. Measured with the defaults: precision 0.994,
// recall 0.984, length 0.964, 29 tips; the length check is the 20%.
TEST_CASE("reconstruct accuracy: thick-branched synthetic tree, three stations, defaults",
          "[accuracy]") {
  const Skeleton truth = test::synthetic_tree(7, {0, 0, 0});
  scanner::HarnessCase c;
  c.stations = 3;
  c.noise = 0.003;
  c.density = 3000;
  const scanner::HarnessResult r = scanner::run_harness(truth, c);
  const SkeletonComparison& a = r.at_radius;
  INFO("points " << r.points << " precision " << a.precision << " recall " << a.recall << " length "
                 << a.length_ratio << " chamfer " << a.chamfer << " tips "
                 << a.branches_reconstructed << "/" << a.branches_truth);
  REQUIRE(r.trees == 1);
  CHECK(a.precision >= 0.9);
  CHECK(a.recall >= 0.9);
  CHECK(a.length_ratio > 0.8);
  CHECK(a.length_ratio < 1.2);
  CHECK(a.branches_reconstructed <= 2 * a.branches_truth);
}

// The same tree with the axis projection switched off (and the centre lines, which remove the
// parallel chains inside fitted stems on their own: length 1.24 with them): the parallel paths
// come back. This shows that the projection is what keeps thick branches to one chain.
TEST_CASE("reconstruct accuracy: thick branches keep parallel paths without the axis projection",
          "[accuracy]") {
  const Skeleton truth = test::synthetic_tree(7, {0, 0, 0});
  scanner::HarnessCase c;
  c.stations = 3;
  c.noise = 0.003;
  ReconstructOptions o;
  o.axis_levels = 0;
  o.contraction_steps = 10;
  o.centre_lines = false;
  const scanner::HarnessResult r = scanner::run_harness(truth, c, o);
  INFO("length " << r.at_radius.length_ratio);
  REQUIRE(r.trees == 1);
  CHECK(r.at_radius.length_ratio > 1.5);
  o.centre_lines = true;
  const scanner::HarnessResult centred = scanner::run_harness(truth, c, o);
  INFO("length with centre lines " << centred.at_radius.length_ratio);
  CHECK(centred.at_radius.length_ratio < r.at_radius.length_ratio);
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
  // Measured: precision 0.974, recall 0.909, length 0.865 (the far side of the trunk and of the
  // limbs is occluded, not the limbs themselves).
  REQUIRE(r.trees == 1);
  CHECK(a.precision >= 0.9);
  CHECK(a.recall >= 0.8);
  CHECK(a.length_ratio > 0.8);
  CHECK(a.length_ratio < 1.2);
}

// The targets (precision within 2 x radius >= 0.9, total length within 20%) on the
// bundled grammar trees scanned from three stations, with the default options. Measured:
// broadleaf 0.989 / 0.888, conifer 0.983 / 0.929, weeping 0.920 / 1.131. Deterministic (fixed
// grammar seed, scanner seed and reconstruction); the checks are the targets themselves, so the
// margins are the distances to them: precision 0.089 / 0.083 / 0.020, length 0.088 / 0.129 /
// 0.069. The fixed-distance recall (1% of the height) is a regression guard: measured 0.96 /
// 0.91 / 0.99.
namespace {

scanner::HarnessResult scan_grammar(const char* grammar, int stations,
                                    const ReconstructOptions& o = {}) {
  SourceManager sources;
  DiagnosticSink diags;
  const Skeleton truth =
      grow_file(std::string(RAMUS_SOURCE_DIR "/examples/trees/") + grammar, {}, sources, diags);
  REQUIRE(truth.size() > 10);
  scanner::HarnessCase c;
  c.stations = stations;
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

TEST_CASE("reconstruct accuracy: bundled broadleaf grammar, three stations, defaults",
          "[accuracy]") {
  check_targets(scan_grammar("broadleaf.ramus", 3), 0.9);
}

TEST_CASE("reconstruct accuracy: bundled conifer grammar, three stations, defaults", "[accuracy]") {
  check_targets(scan_grammar("conifer.ramus", 3), 0.85);
}

TEST_CASE("reconstruct accuracy: bundled weeping grammar, three stations, defaults", "[accuracy]") {
  check_targets(scan_grammar("weeping.ramus", 3), 0.9);
}

// One station sees one side of the crown; the occluded half is missing, so the targets are not
// met. Measured with the defaults (precision within 2 x radius, length, precision within 1% of
// the height): weeping 0.756 / 0.852 / 0.975. Regression guards.
TEST_CASE("reconstruct accuracy: bundled weeping grammar, one station, defaults", "[accuracy]") {
  const scanner::HarnessResult r = scan_grammar("weeping.ramus", 1);
  const SkeletonComparison& a = r.at_radius;
  INFO("points " << r.points << " precision " << a.precision << " length " << a.length_ratio);
  REQUIRE(r.trees == 1);
  CHECK(a.precision >= 0.7);
  CHECK(a.length_ratio > 0.75);
  CHECK(a.length_ratio < 1.2);
  CHECK(a.precision_distance >= 0.9);
}
