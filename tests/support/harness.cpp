#include "tests/support/harness.h"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "compiler/grow.h"

namespace ramus::scanner {

void turn_about_root(Skeleton& t, double degrees) {
  if (degrees == 0 || t.nodes.empty()) return;
  const double a = degrees * M_PI / 180, c = std::cos(a), s = std::sin(a);
  const Vec3 o = t.nodes[0].position;
  auto dir = [&](Vec3& v) { v = Vec3(c * v.x - s * v.y, s * v.x + c * v.y, v.z); };
  auto point = [&](Vec3& p) {
    Vec3 d = p - o;
    dir(d);
    p = o + d;
  };
  for (SkeletonNode& n : t.nodes) point(n.position), dir(n.heading), dir(n.left), dir(n.up);
  for (OrganAnchor& g : t.organs) {
    point(g.position), dir(g.heading), dir(g.left), dir(g.up);
    for (Vec3& v : g.vertices) point(v);
  }
}

std::vector<Vec3> stations_around(const Skeleton& tree, int count) {
  Vec3 lo, hi;
  tree.bounds(lo, hi);
  const double h = std::max(hi.z - lo.z, 1e-6);
  const Vec3 c = (lo + hi) * 0.5;
  std::vector<Vec3> out;
  for (int k = 0; k < count; ++k) {
    const double a = -M_PI / 2 + 2 * M_PI * k / count;
    out.push_back({c.x + 1.5 * h * std::cos(a), c.y + 1.5 * h * std::sin(a), lo.z + 0.015 * h});
  }
  return out;
}

HarnessResult run_harness(const Skeleton& truth, const HarnessCase& c,
                          const ReconstructOptions& options) {
  return run_harness(truth, c,
                     [&](const PointCloud& cloud) { return reconstruct(cloud, options); });
}

Skeleton grow_grammar(const std::string& path, std::uint64_t seed) {
  SourceManager sources;
  DiagnosticSink diags;
  GrowOptions grow;
  if (seed) grow.seed = seed;
  return grow_file(path, grow, sources, diags);
}

HarnessResult run_harness_on_grammar(const std::string& path, const HarnessCase& c,
                                     const ReconstructOptions& options, std::uint64_t seed) {
  const Skeleton truth = grow_grammar(path, seed);
  if (truth.size() < 2) throw std::runtime_error(path + " grows no tree");
  return run_harness(truth, c, options);
}

HarnessResult run_harness(const Skeleton& truth, const HarnessCase& c,
                          const Reconstructor& method) {
  Vec3 lo, hi;
  truth.bounds(lo, hi);
  const double h = std::max(hi.z - lo.z, 1e-6);
  ScanOptions so;
  so.from = stations_around(truth, c.stations);
  so.noise = c.noise;
  so.leaves = c.leaves;
  so.density = c.density;
  so.seed = c.seed;
  so.beam_divergence = c.beam_divergence;
  so.beam_diameter = c.beam_diameter;
  so.range_resolution = c.range_resolution;
  so.registration_error = c.registration_error;
  const ScanResult scan = scan_skeleton(truth, so);
  HarnessResult r;
  r.points = scan.cloud.size();
  const auto t0 = std::chrono::steady_clock::now();
  const ReconstructResult rec = method(scan.cloud);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.trees = rec.trees.size();
  CompareOptions co;
  co.radius_factor = 2.0;
  co.distance = 0.01 * h;
  co.spacing = 0.002 * h;
  // Truth radii are floored at half the scan's point spacing on a surface facing the station at
  // the tree's distance: no scan locates a thinner twig better than that. The floor depends on
  // the scan only, never on the reconstruction (a coarser voxel must not loosen the score).
  co.min_radius = 0.5 / std::sqrt(c.density);
  // Centre-line error per class of truth radius (metres): twigs, branches, limbs, stems.
  co.radius_classes = {0.02, 0.05, 0.1, 0.2, 0.4, 0.65};
  co.scan = &scan.cloud;  // the scores over the wood the scan saw, beside those over all of it
  co.keep_samples = c.keep_samples;
  r.at_radius = compare_skeletons({truth}, rec.trees, co);
  r.reconstructed = rec.trees;
  return r;
}

bool read_scan_flag(int argc, char** argv, int& i, HarnessCase& c) {
  if (i + 1 >= argc) return false;
  const std::string arg = argv[i];
  double* field = arg == "--noise"                ? &c.noise
                  : arg == "--density"            ? &c.density
                  : arg == "--beam-divergence"    ? &c.beam_divergence
                  : arg == "--beam-diameter"      ? &c.beam_diameter
                  : arg == "--range-resolution"   ? &c.range_resolution
                  : arg == "--registration-error" ? &c.registration_error
                                                  : nullptr;
  if (!field) return false;
  *field = std::atof(argv[++i]) * (arg == "--beam-divergence" ? 1e-3 : 1.0);
  return true;
}

}  // namespace ramus::scanner
