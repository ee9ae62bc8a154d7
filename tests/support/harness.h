// The accuracy harness of reconstruction: a grammar's tree -> simulated scan -> reconstruct() ->
// comparison with the known skeleton. Shared by tests/backends/test_reconstruct_accuracy.cpp
// and bench/bench_reconstruct.cpp.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "backends/scanner/scanner.h"
#include "core/skeleton.h"
#include "reconstruct/bsg/compare.h"
#include "reconstruct/reconstruct.h"

namespace ramus::scanner {

struct HarnessCase {
  int stations = 1;  // 1 or more stations evenly spaced around the tree
  // Standard deviation of the range noise in the tree's units (metres for the bundled grammars).
  // 5 mm is the range precision of survey-grade terrestrial scanners at tens of metres.
  double noise = 0.005;
  bool leaves = false;    // also scan the leaf cards (ScanOptions::leaves)
  double density = 3000;  // see ScanOptions::density
  // The beam and the stations' registration (ScanOptions): 0, a line and exact stations.
  double beam_divergence = 0, beam_diameter = 0, range_resolution = 0, registration_error = 0;
  std::uint64_t seed = 1;
  // Keep the truth samples with their centre-line errors (SkeletonComparison::centre_samples).
  bool keep_samples = false;
};

struct HarnessResult {
  std::size_t points = 0;
  std::size_t trees = 0;
  SkeletonComparison at_radius;  // radius-relative and fixed-distance scores
  double seconds = 0;            // reconstruction only
  std::vector<Skeleton> reconstructed;
};

// Stations around the skeleton's base at 1.5 tree heights, tripod height, evenly spaced in
// azimuth starting on the -y side.
std::vector<Vec3> stations_around(const Skeleton& tree, int count);

// `t` turned by `degrees` about the vertical through its first node (frames and organs too):
// the stations then see another side of it.
void turn_about_root(Skeleton& t, double degrees);

// Scans `truth`, reconstructs, compares. The fixed distance is 1% of the tree's height; truth
// radii are floored at half the scan's point spacing (1 / sqrt(density)) at the tree.
HarnessResult run_harness(const Skeleton& truth, const HarnessCase& c,
                          const ReconstructOptions& options = {});

// The same with any reconstruction method (the BSG pipeline above, or the flood fill).
using Reconstructor = std::function<ReconstructResult(const PointCloud&)>;
HarnessResult run_harness(const Skeleton& truth, const HarnessCase& c, const Reconstructor& method);

// The tree a grammar file grows with its derive count and its own seed, or `seed` when not 0
// (empty when it grows none). Shared by the harness and the benches.
Skeleton grow_grammar(const std::string& path, std::uint64_t seed = 0);

// The tree a grammar file grows (its own seed, or `seed` when not 0, and its derive count)
// through run_harness: the setup of the accuracy tests on the bundled grammars. Throws
// std::runtime_error when the grammar grows no tree.
HarnessResult run_harness_on_grammar(const std::string& path, const HarnessCase& c,
                                     const ReconstructOptions& options = {},
                                     std::uint64_t seed = 0);

// The scan flags the benches share, as `ramus scan` names them: --noise S, --density D,
// --beam-divergence MRAD, --beam-diameter D, --range-resolution R, --registration-error S.
// Reads the one at argv[i] into c and steps i over its value; false when argv[i] is none of them.
bool read_scan_flag(int argc, char** argv, int& i, HarnessCase& c);

}  // namespace ramus::scanner
