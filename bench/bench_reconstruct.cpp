// Reconstruction benchmark and accuracy report (docs/reconstruction.md):
//   bench_reconstruct accuracy GRAMMAR...   grammar tree -> simulated scans (1 and 3 stations,
//                                            noise 0.3% of the height) -> reconstruct -> scores
//   bench_reconstruct time SCAN...          reconstruction time of real scans
//   bench_reconstruct scene GRAMMAR N       N trees of GRAMMAR scanned into one ~1M-point cloud
// Prints one line per run and the peak resident memory at the end.
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "backends/mesh/tree_mesh.h"
#include "backends/scanner/harness.h"
#include "compiler/grow.h"
#include "formats/point_cloud_io.h"

using namespace ramus;

namespace {

Skeleton grow(const std::string& path, std::uint64_t seed = 0) {
  SourceManager sources;
  DiagnosticSink diags;
  GrowOptions o;
  if (seed) o.seed = seed;
  return grow_file(path, o, sources, diags);
}

void accuracy(const std::string& path) {
  const Skeleton t = grow(path);
  for (int stations : {1, 3}) {
    scanner::HarnessCase c;
    c.stations = stations;
    const scanner::HarnessResult r = scanner::run_harness(t, c);
    const SkeletonComparison& a = r.at_radius;
    std::printf("%s stations=%d points=%zu trees=%zu precision(2r)=%.3f recall(2r)=%.3f "
                "precision(1%%h)=%.3f recall(1%%h)=%.3f chamfer=%.4f length=%.3f "
                "tips=%zu/%zu time=%.2fs\n",
                path.c_str(), stations, r.points, r.trees, a.precision, a.recall,
                a.precision_distance, a.recall_distance, a.chamfer, a.length_ratio,
                a.branches_reconstructed, a.branches_truth, r.seconds);
  }
}

void time_scan(const std::string& path) {
  const PointCloud cloud = read_point_cloud(path);
  const ReconstructResult r = reconstruct(cloud);
  std::printf("%s points=%zu trees=%zu nodes=%zu bases=%.3f graph=%.3f forest=%.3f refine=%.3f "
              "inflate=%.3f total=%.3fs\n",
              path.c_str(), cloud.size(), r.trees.size(), r.counts.skeleton_nodes,
              r.timings.bases, r.timings.graph, r.timings.forest, r.timings.refine,
              r.timings.inflate, r.timings.total);
}

void scene(const std::string& path, int n) {
  // N trees in a row, each from its own seed, meshed together and scanned from both sides.
  std::vector<Vec3> vertices;
  std::vector<std::uint32_t> indices;
  double height = 0, spacing = 0;
  for (int k = 0; k < n; ++k) {
    Skeleton s = grow(path, std::uint64_t(k + 1));
    Vec3 lo, hi;
    s.bounds(lo, hi);
    height = std::max(height, hi.z - lo.z);
    if (k == 0) spacing = 0.8 * std::max(hi.x - lo.x, hi.y - lo.y);
    for (auto& node : s.nodes) node.position.x += spacing * k;
    for (auto& o : s.organs) o.position.x += spacing * k;
    const mesh::TreeMesh m = mesh::build_tree_mesh(s, {});
    const auto base = std::uint32_t(vertices.size());
    for (const Vec3f& p : m.bark.positions) vertices.push_back(Vec3(p));
    for (std::uint32_t i : m.bark.indices) indices.push_back(base + i);
  }
  scanner::ScanOptions so;
  const double mid = spacing * (n - 1) / 2;
  so.from = {{mid, -2.0 * height, 0.02 * height}, {mid, 2.0 * height, 0.02 * height}};
  so.noise = 0.003 * height;
  so.density = 6000;
  const scanner::ScanResult scan = scanner::scan_triangles(vertices, indices, so);
  const ReconstructResult r = reconstruct(scan.cloud);
  std::printf("scene of %d x %s: points=%zu trees=%zu nodes=%zu bases=%.3f graph=%.3f "
              "forest=%.3f refine=%.3f inflate=%.3f total=%.3fs\n",
              n, path.c_str(), scan.cloud.size(), r.trees.size(), r.counts.skeleton_nodes,
              r.timings.bases, r.timings.graph, r.timings.forest, r.timings.refine,
              r.timings.inflate, r.timings.total);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: bench_reconstruct accuracy|time FILE... | scene GRAMMAR N\n");
    return 2;
  }
  try {
    const std::string mode = argv[1];
    if (mode == "scene") {
      scene(argv[2], argc > 3 ? std::atoi(argv[3]) : 4);
    } else {
      for (int i = 2; i < argc; ++i) mode == "time" ? time_scan(argv[i]) : accuracy(argv[i]);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_reconstruct: %s\n", e.what());
    return 1;
  }
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  std::printf("peak memory: %.1f MB\n", double(ru.ru_maxrss) / 1024.0);
  return 0;
}
