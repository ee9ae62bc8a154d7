// The accuracy harness: trees with known skeletons -> simulated scans (one and three stations,
// with range noise) -> reconstruct() -> comparison with the truth. The thresholds below are the
// issue's targets where the implementation meets them and regression guards elsewhere
// (docs/reconstruction.md lists the measured values); each case states its margins.
#include <catch2/catch.hpp>
#include <string>

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

// A beam of some width (a phase-shift scanner's: 0.3 mrad, 2.1 mm at the exit, one echo per beam)
// puts mixed points between twig edges and what lies behind them, alone in the air. Each became
// a spur; ignored as stray points (reconstruct/bsg/stray_points.h) they do not. Measured:
// precision 0.996 / recall 0.998 against 0.956 / 0.993 with the stray points kept (on thick_oak,
// bench_reconstruct --beam-divergence 0.3 --beam-diameter 0.0021: 0.985 against 0.741).
TEST_CASE("reconstruct accuracy: mixed points of a wide beam do not grow branches", "[accuracy]") {
  const Skeleton truth = test::synthetic_tree(7, {0, 0, 0});
  scanner::HarnessCase c;
  c.stations = 3;
  c.noise = 0.003;
  c.beam_divergence = 0.3e-3;
  c.beam_diameter = 0.0021;
  const scanner::HarnessResult r = scanner::run_harness(truth, c);
  ReconstructOptions kept;
  kept.remove_stray = false;
  const scanner::HarnessResult k = scanner::run_harness(truth, c, kept);
  INFO("precision " << r.at_radius.precision << " recall " << r.at_radius.recall
                    << "; stray points kept: precision " << k.at_radius.precision);
  REQUIRE(r.trees == 1);
  CHECK(r.at_radius.precision >= 0.98);
  CHECK(r.at_radius.recall >= 0.98);
  CHECK(k.at_radius.precision < r.at_radius.precision - 0.02);
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

// The targets (precision within 2 x radius >= 0.9, recall within 2 x radius >= 0.9,
// total length within 20%) on the bundled grammar trees scanned from three stations, with the
// default options. Measured (precision / recall / length): broadleaf 0.979 / 0.935 / 0.935,
// conifer 0.979 / 0.931 / 0.975, weeping 0.961 / 0.963 / 1.002. The recalls were 0.904 / 0.818 /
// 0.925 before the tips walked on to the last samples ahead of them (tip_extension.h), and the
// conifer's 0.885 while the terrain layer took the drooping ends of its lowest whorls
// (ground_surface.h). Deterministic (fixed grammar seed, scanner seed and reconstruction); the
// checks are the targets themselves. The fixed-distance recall (1% of the height) is a
// regression guard.
namespace {

scanner::HarnessResult scan_grammar(const char* grammar, int stations,
                                    const ReconstructOptions& o = {}, std::uint64_t seed = 0) {
  scanner::HarnessCase c;
  c.stations = stations;
  return scanner::run_harness_on_grammar(std::string(RAMUS_SOURCE_DIR "/examples/trees/") + grammar,
                                         c, o, seed);
}

void check_targets(const scanner::HarnessResult& r, double min_recall_distance) {
  const SkeletonComparison& a = r.at_radius;
  INFO("points " << r.points << " trees " << r.trees << " precision " << a.precision << " recall "
                 << a.recall << " precision(1%h) " << a.precision_distance << " recall(1%h) "
                 << a.recall_distance << " length " << a.length_ratio);
  REQUIRE(r.trees == 1);
  CHECK(a.precision >= 0.9);
  CHECK(a.recall >= 0.9);
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

// The weeping tree's whips from three stations: the precision of 0.95 within 2 x radius.
// Each degree-2 collapse kept the two vertices it joined within the branch's radius of the new
// polyline, but not the vertices they had taken in before, in this round or an earlier one: on
// the arching whips the chords came to lie 2-4 cm under the truth (radius 1.2 cm), precision
// 0.925. Checked against every position a vertex took in (inflate.cpp): 0.961.
TEST_CASE("reconstruct accuracy: bundled weeping grammar, three stations, defaults", "[accuracy]") {
  const scanner::HarnessResult r = scan_grammar("weeping.ramus", 3);
  check_targets(r, 0.9);
  CHECK(r.at_radius.precision >= 0.95);
}

// The weeping tree scanned with that beam: between whips a few centimetres apart the mixed points
// come in runs of three or so (one scan line's neighbouring beams at one edge), each point with
// two others within reach, and the gap bridging chained the runs into branches through the air.
// With clusters of fewer than five points stray too (ReconstructOptions::stray_cluster = 5, an
// option: it cost some real scans) the 0.95 is met. Measured: precision / recall
// 0.956 / 0.963, with the neighbour test alone (the default) 0.940 / 0.953.
TEST_CASE("reconstruct accuracy: weeping grammar with a wide beam, runs of mixed points",
          "[accuracy]") {
  scanner::HarnessCase c;
  c.stations = 3;
  c.beam_divergence = 0.3e-3;
  c.beam_diameter = 0.0021;
  const std::string path = RAMUS_SOURCE_DIR "/examples/trees/weeping.ramus";
  ReconstructOptions runs;
  runs.stray_cluster = 5;
  const scanner::HarnessResult r = scanner::run_harness_on_grammar(path, c, runs);
  const scanner::HarnessResult s = scanner::run_harness_on_grammar(path, c, {});
  INFO("precision " << r.at_radius.precision << " recall " << r.at_radius.recall
                    << "; neighbour test alone: precision " << s.at_radius.precision << " recall "
                    << s.at_radius.recall);
  REQUIRE(r.trees == 1);
  CHECK(r.at_radius.precision >= 0.95);
  CHECK(r.at_radius.recall >= 0.9);
  CHECK(s.at_radius.precision < r.at_radius.precision - 0.01);
}

// One station sees one side of the crown; the occluded half is missing, so the targets are not
// met. Measured with the defaults (precision within 2 x radius, length, precision within 1% of
// the height): weeping 0.665 / 0.877 / 0.970. Regression guards. (0.739 while the trunk radius
// came from one algebraic circle: 0.185 m on the half-ring this scan sees, truth 0.275 m; the
// robust fits measure 0.271 m, and at that scale the pipe model's radii of the whips are 1.3-1.6 x
// theirs, which costs the inflation's clustering: docs/reconstruction.md, Deviations.)
TEST_CASE("reconstruct accuracy: bundled weeping grammar, one station, defaults", "[accuracy]") {
  const scanner::HarnessResult r = scan_grammar("weeping.ramus", 1);
  const SkeletonComparison& a = r.at_radius;
  INFO("points " << r.points << " precision " << a.precision << " length " << a.length_ratio);
  REQUIRE(r.trees == 1);
  CHECK(a.precision >= 0.64);
  CHECK(a.length_ratio > 0.75);
  CHECK(a.length_ratio < 1.2);
  CHECK(a.precision_distance >= 0.9);
}

// Centre lines (issue 19): an 8 m tree with a 30 cm trunk and limbs of 5-20 cm, thick enough
// that the shortest paths of the BSG run along the bark. Without centre lines (measured): median
// centre-line error / radius 0.43 over the 2-40 cm classes, length 3.95 x the truth with 318 tips
// for 25. With them: 0.056 / 0.020 / 0.104 / 0.003 in the classes 2-5 / 5-10 / 10-20 / 20-40 cm,
// precision / recall within 2 x radius 0.999 / 0.992, length 1.51, 48 tips. Now, with the copies
// of stems on one axis joined (coincident_chains.h), 1.000 / 0.995, length 1.01 (1.12 without).
namespace {

// Which samples a class median is over: all of the class's, the ones the reconstruction found
// (within 2 x radius), or the ones the scan saw.
enum class Over { all, found, seen };

// Every radius class from `lo` up with at least 100 such samples has its median <= bound.
void check_centre_classes(const SkeletonComparison& a, double lo, double bound, Over over) {
  for (const CentreError& e : a.centre_error) {
    if (e.lo < lo || (over == Over::seen ? e.seen : e.samples) < 100) continue;
    INFO("radii " << e.lo << "-" << e.hi << ": median " << e.median << ", found " << e.median_found
                  << ", seen " << e.median_seen << ", n " << e.samples << ", seen " << e.seen);
    CHECK((over == Over::all     ? e.median
           : over == Over::found ? e.median_found
                                 : e.median_seen) <= bound);
  }
}

}  // namespace

TEST_CASE("reconstruct accuracy: thick tree, three stations: nodes on the axes", "[accuracy]") {
  const Skeleton truth = test::thick_tree(5, 8.0, 0.3);
  scanner::HarnessCase c;
  c.stations = 3;
  const scanner::HarnessResult r = scanner::run_harness(truth, c);
  const SkeletonComparison& a = r.at_radius;
  INFO("precision " << a.precision << " recall " << a.recall << " length " << a.length_ratio
                    << " tips " << a.branches_reconstructed);
  REQUIRE(r.trees == 1);
  CHECK(a.precision >= 0.95);
  CHECK(a.recall >= 0.9);
  check_centre_classes(a, 0.05, 0.15, Over::all);
  CHECK(a.length_ratio < 1.1);
  ReconstructOptions off;
  off.centre_lines = false;
  const scanner::HarnessResult b = scanner::run_harness(truth, c, off);
  INFO("without centre lines: median " << b.at_radius.centre_error_median << ", length "
                                       << b.at_radius.length_ratio);
  CHECK(b.at_radius.centre_error_median > 2 * a.centre_error_median);
}

// One station sees half of every stem. Measured: precision / recall within 2 x radius 0.959 /
// 0.904, median error / radius 0.072 / 0.120 / 0.052 in the classes 5-10 / 10-20 / 20-40 cm
// over all samples, 0.060 / 0.115 / 0.052 over the found ones. Until hidden limbs were bridged
// (bridge.h) the recall was 0.798: a 10-12 cm limb seen only beyond the trunk was dropped.
// Cross-sections alone left the limbs at 0.60 / 0.28 (found 0.43 / 0.135): the chain cylinders
// and bridges (chain_cylinders.h) put them on their axes; before the forks were placed where
// the axes meet (fork_placement.h) the 10-20 cm class was at 0.194 over all samples, its limbs
// hung from the crotches.
TEST_CASE("reconstruct accuracy: thick tree, one station: trunk and limbs on their axes",
          "[accuracy]") {
  const Skeleton truth = test::thick_tree(5, 8.0, 0.3);
  scanner::HarnessCase c;
  c.stations = 1;
  const scanner::HarnessResult r = scanner::run_harness(truth, c);
  const SkeletonComparison& a = r.at_radius;
  INFO("precision " << a.precision << " recall " << a.recall);
  REQUIRE(r.trees == 1);
  // 0.967 until forks were kept from walking in the edge removal (inflate.cpp, kForkDrift), 0.949
  // since: a 2 cm twig in the crown whose chain runs out, back and out again (its 4 cm band is
  // what precision within 2 x radius allows); the tree turned by 60-240 degrees gives 0.973-0.992.
  CHECK(a.precision >= 0.94);
  CHECK(a.recall >= 0.9);
  check_centre_classes(a, 0.05, 0.15, Over::found);
  // Over all samples too, a limb hidden behind the trunk included.
  check_centre_classes(a, 0.05, 0.15, Over::all);
  // The scan sees 84 % of the tree's samples; of those the reconstruction finds 0.968 (measured;
  // 0.896 before the hidden limbs).
  INFO("seen " << a.seen_fraction << " recall seen " << a.recall_seen);
  CHECK(a.seen_fraction > 0.75);
  CHECK(a.recall_seen >= 0.95);
  check_centre_classes(a, 0.05, 0.15, Over::seen);
}

// The thick tree grown from seeds that no parameter was chosen on (the cases above and the
// documented measures use seed 5; `bench_reconstruct accuracy --tree-seed N thick-small`), one
// station each: the acceptance of issue 19 for one-sided scans must hold on trees it was not
// tuned on. Measured, seeds 1 / 2 / 3: precision 0.987 / 0.992 / 0.981, recall 0.932 / 0.949 /
// 0.916, seen class medians from 5 cm at most 0.033 / 0.047 / 0.038 r.
TEST_CASE("reconstruct accuracy: thick trees from other seeds, one station", "[accuracy]") {
  for (std::uint64_t seed : {1, 2, 3}) {
    const Skeleton truth = test::thick_tree(seed, 8.0, 0.3);
    scanner::HarnessCase c;
    c.stations = 1;
    const scanner::HarnessResult r = scanner::run_harness(truth, c);
    const SkeletonComparison& a = r.at_radius;
    INFO("seed " << seed << ": precision " << a.precision << " recall " << a.recall);
    REQUIRE(r.trees == 1);
    CHECK(a.precision >= 0.95);
    CHECK(a.recall >= 0.9);
    check_centre_classes(a, 0.05, 0.15, Over::seen);
  }
}

// Every parameter was chosen on scans of 3000 points per square metre (1.8 cm spacing); real
// scans are sparser or denser by several times. The thick trees at a third of it (3.2 cm) and at
// twice (1.3 cm), one station (`bench/reconstruct_suite.sh densities`). Measured, 8 m tree at 1000
// / 6000: precision 0.980 / 0.988, recall 0.907 / 0.953, recall over the seen wood 0.989 / 0.998,
// seen class medians from 5 cm at most 0.063 / 0.023 r; the 14 m tree 0.990 / 0.980, 0.909 /
// 0.944, 0.985 / 0.997, at most 0.053 / 0.026 r. From one station a third of the density drops
// the share of the 8 m tree the scan sees from 0.84 to 0.58 (fewer bark points on the 60 degrees
// a seen sample needs); the recall over the seen wood stays.
TEST_CASE("reconstruct accuracy: thick trees at a third of and twice the scan density",
          "[accuracy]") {
  struct Case {
    double height, trunk;
    std::uint64_t seed;
    double density;
  };
  for (const Case& k : {Case{8.0, 0.3, 5, 1000}, Case{8.0, 0.3, 5, 6000}, Case{14.0, 0.6, 11, 1000},
                        Case{14.0, 0.6, 11, 6000}}) {
    const Skeleton truth = test::thick_tree(k.seed, k.height, k.trunk);
    scanner::HarnessCase c;
    c.stations = 1;
    c.density = k.density;
    const scanner::HarnessResult r = scanner::run_harness(truth, c);
    const SkeletonComparison& a = r.at_radius;
    INFO(k.height << " m tree, " << k.density << " points / m2: precision " << a.precision
                  << " recall " << a.recall << " recall seen " << a.recall_seen);
    REQUIRE(r.trees == 1);
    CHECK(a.precision >= 0.95);
    CHECK(a.recall >= 0.9);
    CHECK(a.recall_seen >= 0.95);
    check_centre_classes(a, 0.05, 0.15, Over::seen);
  }
}

// The bundled grammars grown from seeds no parameter was chosen on (docs/reconstruction.md,
// *Trees no parameter was chosen on*). Three stations, measured, precision / recall within 2 x
// radius: thick_oak from seed 2 0.998 / 0.991, the conifer from seed 1 0.976 / 0.930, the weeping
// tree from seed 2 0.963 / 0.966, the broadleaf from seed 3 0.956 / 0.852. That broadleaf has 3,301
// nodes (1,730 from seed 4, 2,015 from its own, 7), twigs of 1-2 cm radius over 42% of its length,
// and a fifth of its wood carries no scan point over 60 degrees of its bark: its recall is checked
// over the seen wood (0.942).
// One station, thick_oak from seed 5: the fork node at the trunk's foot had its slab cut across a
// 47-degree edge from the root and took a 0.43 m circle (truth 0.6) near the residual bound; every
// clean trunk ring above it up to 4 m then failed the no-thickening test against it, and the trunk
// ran from 0.3 m off its axis at the foot (40-65 cm class 0.215 r). A firm ring is measured against
// the nearest firm one below it.
TEST_CASE("reconstruct accuracy: bundled grammars from other seeds", "[accuracy]") {
  struct Case {
    const char* grammar;
    std::uint64_t seed;
    int stations;
    double recall_seen;  // the least recall within 2 x radius over the seen wood
    bool recall_all;     // recall over all samples checked too, not only over the seen ones
  };
  for (const Case& k :
       {Case{"thick_oak.ramus", 2, 3, 0.9, true}, Case{"conifer.ramus", 1, 3, 0.9, true},
        Case{"weeping.ramus", 2, 3, 0.9, true}, Case{"broadleaf.ramus", 3, 3, 0.9, false},
        Case{"thick_oak.ramus", 5, 1, 0.95, false}}) {
    const scanner::HarnessResult r = scan_grammar(k.grammar, k.stations, {}, k.seed);
    const SkeletonComparison& a = r.at_radius;
    INFO(k.grammar << " seed " << k.seed << ", " << k.stations << " station(s): precision "
                   << a.precision << " recall " << a.recall << " recall seen " << a.recall_seen);
    REQUIRE(r.trees == 1);
    CHECK(a.precision >= 0.95);
    CHECK(a.recall_seen >= k.recall_seen);
    if (k.recall_all) CHECK(a.recall >= 0.9);
    check_centre_classes(a, 0.05, 0.15, Over::seen);
  }
}

TEST_CASE("reconstruct accuracy: the weeping tree's leader, one station, seed 1", "[accuracy]") {
  // A limb full of hanging twigs outweighs the leader it leaves at 5.8 m: bridges that followed
  // the heaviest child laid the leader's nodes on chords 0.5-0.9 r off its axis (seen 5-10 /
  // 10-20 cm classes 0.182 / 0.192 r; 0.150 / 0.106 since they follow the stem's child,
  // chain_cylinders.h). Bounds with room for the scanner's and the compilers' last bits.
  const scanner::HarnessResult r = scan_grammar("weeping.ramus", 1, {}, 1);
  const SkeletonComparison& a = r.at_radius;
  REQUIRE(r.trees == 1);
  for (const CentreError& e : a.centre_error) {
    INFO("radii " << e.lo << "-" << e.hi << ": seen median " << e.median_seen << ", seen "
                  << e.seen);
    if (e.lo == 0.05) CHECK(e.median_seen <= 0.16);
    if (e.lo == 0.1) CHECK(e.median_seen <= 0.13);
  }
  CHECK(a.recall_seen >= 0.85);
}
