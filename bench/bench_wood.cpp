// Wood/leaf separation benchmark (docs/wood-separation.md):
//   bench_wood separate [--stations N] GRAMMAR...  simulated scans with and without leaf cards
//       (N stations, 1 and 3 by default, range noise 5 mm): wood precision and recall against the
//       scanner's per-return labels, the fraction of wood kept on the bark-only scan, time
//   bench_wood reconstruct [--stations N] GRAMMAR...  leafy scans reconstructed with the leaves
//       kept, removed, and auto (ReconstructOptions::leaves_in_scan): skeleton accuracy
//   bench_wood real SCAN...  real scans: the fraction classified leaf, and the number of trees
//       reconstructed with the leaves kept and with auto
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

#include "backends/scanner/scanner.h"
#include "compiler/grow.h"
#include "formats/point_cloud_io.h"
#include "reconstruct/reconstruct.h"
#include "reconstruct/wood/wood_separation.h"
#include "tests/support/harness.h"

using namespace ramus;

namespace {

using Clock = std::chrono::steady_clock;

Skeleton grow(const std::string& path) {
  SourceManager sources;
  DiagnosticSink diags;
  return grow_file(path, GrowOptions{}, sources, diags);
}

std::vector<int> g_stations = {1, 3};

// The harness's scan (harness.cpp: noise 5 mm, density 3000, stations around the tree).
scanner::ScanResult scan(const Skeleton& t, int stations, bool leaves) {
  scanner::ScanOptions so;
  so.from = scanner::stations_around(t, stations);
  so.noise = 0.005;
  so.density = 3000;
  so.leaves = leaves;
  return scanner::scan_skeleton(t, so);
}

void separate(const std::string& path) {
  const Skeleton t = grow(path);
  for (int stations : g_stations) {
    const scanner::ScanResult leafy = scan(t, stations, true);
    const std::vector<std::uint8_t> leaf = scanner::leaf_returns(t, leafy);
    const auto t0 = Clock::now();
    const WoodSeparation ws = separate_wood(leafy.cloud);
    const double sec = std::chrono::duration<double>(Clock::now() - t0).count();
    std::size_t tp = 0, pred = 0, truth = 0;
    for (std::size_t i = 0; i < leaf.size(); ++i) {
      truth += !leaf[i];
      pred += ws.wood[i];
      tp += ws.wood[i] && !leaf[i];
    }
    const scanner::ScanResult bark = scan(t, stations, false);
    const WoodSeparation wb = separate_wood(bark.cloud);
    std::size_t kept = 0;
    for (std::uint8_t w : wb.wood) kept += w;
    std::printf(
        "%s stations=%d points=%zu true_leaf=%.3f leaf_fraction=%.3f D=%.2f wood_precision=%.3f "
        "wood_recall=%.3f | bark-only: points=%zu D=%.2f wood_kept=%.4f | time=%.2fs\n",
        path.c_str(), stations, leaf.size(), 1.0 - double(truth) / double(leaf.size()),
        ws.leaf_fraction, ws.separation, pred ? double(tp) / double(pred) : 0.0,
        truth ? double(tp) / double(truth) : 0.0, bark.cloud.size(), wb.separation,
        double(kept) / double(bark.cloud.size()), sec);
  }
}

void reconstruct_cases(const std::string& path) {
  const Skeleton t = grow(path);
  const char* names[] = {"keep", "remove", "auto"};
  const LeafHandling modes[] = {LeafHandling::kKeep, LeafHandling::kRemove, LeafHandling::kAuto};
  for (int stations : g_stations) {
    scanner::HarnessCase c;
    c.stations = stations;
    c.leaves = true;
    for (int k = 0; k < 3; ++k) {
      ReconstructOptions o;
      o.leaves_in_scan = modes[k];
      const scanner::HarnessResult r = scanner::run_harness(t, c, o);
      const SkeletonComparison& a = r.at_radius;
      std::printf(
          "%s stations=%d leaves=%s points=%zu trees=%zu precision(2r)=%.3f recall(2r)=%.3f "
          "precision(1%%h)=%.3f recall(1%%h)=%.3f chamfer=%.4f length=%.3f tips=%zu/%zu "
          "time=%.2fs\n",
          path.c_str(), stations, names[k], r.points, r.trees, a.precision, a.recall,
          a.precision_distance, a.recall_distance, a.chamfer, a.length_ratio,
          a.branches_reconstructed, a.branches_truth, r.seconds);
    }
  }
}

void real(const std::string& path) {
  const PointCloud cloud = read_point_cloud(path);
  const auto t0 = Clock::now();
  const WoodSeparation ws = separate_wood(cloud);
  const double sec = std::chrono::duration<double>(Clock::now() - t0).count();
  ReconstructOptions keep, automatic;
  automatic.leaves_in_scan = LeafHandling::kAuto;
  const ReconstructResult rk = reconstruct(cloud, keep), ra = reconstruct(cloud, automatic);
  std::printf(
      "%s points=%zu leaf_fraction=%.3f D=%.2f scale=%.3f time=%.2fs trees(keep)=%zu "
      "trees(auto)=%zu nodes(keep)=%zu nodes(auto)=%zu\n",
      path.c_str(), cloud.size(), ws.leaf_fraction, ws.separation, ws.scale, sec, rk.trees.size(),
      ra.trees.size(), rk.counts.skeleton_nodes, ra.counts.skeleton_nodes);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: bench_wood separate|reconstruct|real [--stations N] FILE...\n");
    return 2;
  }
  try {
    const std::string mode = argv[1];
    for (int i = 2; i < argc; ++i) {
      if (std::strcmp(argv[i], "--stations") == 0 && i + 1 < argc) {
        g_stations = {std::atoi(argv[++i])};
      } else if (mode == "separate") {
        separate(argv[i]);
      } else if (mode == "reconstruct") {
        reconstruct_cases(argv[i]);
      } else if (mode == "real") {
        real(argv[i]);
      } else {
        throw std::runtime_error("unknown mode " + mode);
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_wood: %s\n", e.what());
    return 1;
  }
  return 0;
}
