// Flood-fill skeletons against the BSG method, and branch merging (docs/flood-fill.md,
// docs/branch-merging.md):
//   bench_flood accuracy [SCAN FLAGS] [--stray-cluster N] GRAMMAR...
//                                    grammar tree -> simulated scans (1 and 3 stations, range
//                                    noise 5 mm; the scan flags of bench_reconstruct, as `ramus
//                                    scan`: --noise, --density, --beam-divergence, --beam-diameter,
//                                    --range-resolution, --registration-error) -> BSG and flood
//                                    -> scores and time; stray clusters of fewer than N points
//                                    (both methods; default theirs)
//   bench_flood time SCAN...         BSG and flood times on real scans
//   bench_flood merge FILE...        a grammar tree (.ramus) or the flood skeleton of a scan:
//                                    nodes and bark triangles against the Chamfer distance to the
//                                    unmerged skeleton, for several alpha,beta
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "formats/point_cloud_io.h"
#include "mesh/tree_mesh.h"
#include "reconstruct/flood/flood_skeleton.h"
#include "reconstruct/merge/branch_merge.h"
#include "tests/reconstruct/reconstruct_fixtures.h"
#include "tests/support/harness.h"

using namespace ramus;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

bool ends_with(const std::string& s, const char* tail) {
  const std::size_t n = std::strlen(tail);
  return s.size() >= n && s.compare(s.size() - n, n, tail) == 0;
}

void print_row(const char* method, const std::string& path, int stations, std::size_t points,
               const ReconstructResult& r, const SkeletonComparison& a, double seconds) {
  std::printf(
      "%-6s %s stations=%d points=%zu trees=%zu nodes=%zu precision(2r)=%.3f "
      "recall(2r)=%.3f precision(1%%h)=%.3f recall(1%%h)=%.3f chamfer=%.4f length=%.3f "
      "tips=%zu/%zu time=%.3fs centre/r=%.3f\n",
      method, path.c_str(), stations, points, r.trees.size(), r.counts.skeleton_nodes, a.precision,
      a.recall, a.precision_distance, a.recall_distance, a.chamfer, a.length_ratio,
      a.branches_reconstructed, a.branches_truth, seconds, a.centre_error_median);
}

// The accuracy harness of tests/support/harness.h, run for both methods on the same scan.
void accuracy(const std::string& path, const scanner::HarnessCase& base, int stray_cluster) {
  // "thick-small" and "thick": the 8 m, 30 cm and the 14 m, 60 cm trunk trees of
  // tests/reconstruct/reconstruct_fixtures.h.
  const Skeleton truth = path == "thick-small" ? test::thick_tree(5, 8.0, 0.3)
                         : path == "thick"     ? test::thick_tree(11, 14.0, 0.6)
                                               : scanner::grow_grammar(path);
  for (int stations : {1, 3}) {
    scanner::HarnessCase hc = base;
    hc.stations = stations;
    // flood-raw: the flood fill without centre lines.
    for (const char* method : {"bsg", "flood", "flood-raw"}) {
      ReconstructResult last;
      const scanner::HarnessResult h =
          scanner::run_harness(truth, hc, [&](const PointCloud& cloud) {
            flood::FloodOptions fo;
            fo.centre_lines = std::strcmp(method, "flood-raw") != 0;
            ReconstructOptions ro;
            if (stray_cluster >= 0)
              fo.stray_cluster = ro.stray_cluster = std::size_t(stray_cluster);
            last = std::strcmp(method, "bsg") == 0 ? reconstruct(cloud, ro)
                                                   : flood::flood_reconstruct(cloud, fo);
            return last;
          });
      print_row(method, path, stations, h.points, last, h.at_radius, h.seconds);
    }
  }
}

void time_scan(const std::string& path) {
  const PointCloud cloud = read_point_cloud(path);
  const ReconstructResult b = reconstruct(cloud);
  const ReconstructResult f = flood::flood_reconstruct(cloud);
  std::printf(
      "%s points=%zu bsg: trees=%zu nodes=%zu total=%.3fs | flood: trees=%zu nodes=%zu "
      "bases=%.3f voxels=%.3f flood=%.3f centre lines=%.3f total=%.3fs | speed-up %.1fx\n",
      path.c_str(), cloud.size(), b.trees.size(), b.counts.skeleton_nodes, b.timings.total,
      f.trees.size(), f.counts.skeleton_nodes, f.timings.bases, f.timings.graph, f.timings.forest,
      f.timings.inflate, f.timings.total, b.timings.total / std::max(f.timings.total, 1e-9));
}

std::size_t bark_triangles(const Skeleton& s) {
  return mesh::build_tree_mesh(s, {}).bark.triangle_count();
}

void merging(const std::string& path) {
  Skeleton base;
  if (ends_with(path, ".ramus")) {
    base = scanner::grow_grammar(path);
  } else {
    const ReconstructResult r = flood::flood_reconstruct(read_point_cloud(path));
    if (r.trees.empty()) throw std::runtime_error(path + ": no tree");
    base = r.trees.front();
  }
  base.organs.clear();  // bark only: leaves do not change with merging
  Vec3 lo, hi;
  base.bounds(lo, hi);
  const double h = std::max(hi.z - lo.z, 1e-6);
  CompareOptions co;
  co.distance = 0.01 * h;
  co.spacing = 0.002 * h;
  const std::size_t tri0 = bark_triangles(base);
  const std::pair<double, double> settings[] = {{0, 0}, {5, 5}, {10, 15}, {20, 30}, {30, 45}};
  for (const auto& [alpha, beta] : settings) {
    Skeleton s = base;
    const auto t0 = Clock::now();
    const merge::MergeStats st = merge::merge_branches(s, {alpha, beta});
    const double seconds = seconds_since(t0);
    const SkeletonComparison c = compare_skeletons({base}, {s}, co);
    const std::size_t tri = bark_triangles(s);
    std::printf(
        "%s alpha=%g beta=%g nodes=%zu->%zu (%.1f%%) vertical=%zu horizontal=%zu "
        "triangles=%zu->%zu (%.1f%%) chamfer=%.5f (%.3f%% of height) length=%.3f "
        "time=%.4fs\n",
        path.c_str(), alpha, beta, st.nodes_before, st.nodes_after,
        100.0 * double(st.nodes_after) / double(std::max<std::size_t>(1, st.nodes_before)),
        st.vertical_merges, st.horizontal_merges, tri0, tri,
        100.0 * double(tri) / double(std::max<std::size_t>(1, tri0)), c.chamfer,
        100 * c.chamfer / h, c.length_ratio, seconds);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: bench_flood accuracy GRAMMAR... | time SCAN... | merge FILE...\n");
    return 2;
  }
  try {
    const std::string mode = argv[1];
    scanner::HarnessCase scan_case;
    int stray_cluster = -1;
    for (int i = 2; i < argc; ++i) {
      const std::string arg = argv[i];
      if (mode == "accuracy" && scanner::read_scan_flag(argc, argv, i, scan_case)) {
        continue;
      } else if (mode == "accuracy" && arg == "--stray-cluster" && i + 1 < argc) {
        stray_cluster = std::atoi(argv[++i]);
      } else if (mode == "accuracy") {
        accuracy(argv[i], scan_case, stray_cluster);
      } else if (mode == "time") {
        time_scan(argv[i]);
      } else if (mode == "merge") {
        merging(argv[i]);
      } else {
        std::fprintf(stderr, "bench_flood: unknown mode '%s'\n", mode.c_str());
        return 2;
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_flood: %s\n", e.what());
    return 1;
  }
  return 0;
}
