// separate_wood() on simulated scans with the scanner's per-return labels (bark-only scans keep
// their wood, leafy scans lose most of their leaves), on real scans (none loses its trunk), on bad
// input, and reconstruct() with the leaves removed.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>

// Measured on the 1-station leafy broadleaf scan (docs/wood-separation.md): wood precision 0.666,
// wood recall 0.636; the thresholds below leave a margin.

#include "../skeleton_infer/skeleton_fixtures.h"
#include "backends/scanner/scanner.h"
#include "formats/point_cloud_io.h"
#include "reconstruct/reconstruct.h"
#include "reconstruct/wood/wood_separation.h"

using namespace ramus;

namespace {

Skeleton grow(const std::string& name) {
  return skeleton_test::grow_example("examples/trees/" + name + ".ramus");
}

// One station (the scanner's default), 5 mm range noise; density 1000 is fast, 3000 is the
// density of the measurements in docs/wood-separation.md.
scanner::ScanResult scan(const Skeleton& t, bool leaves, std::uint64_t seed = 1,
                         double density = 1000) {
  scanner::ScanOptions so;
  so.noise = 0.005;
  so.density = density;
  so.leaves = leaves;
  so.seed = seed;
  return scanner::scan_skeleton(t, so);
}

struct Scores {
  double wood_precision = 0, wood_recall = 0, leaf_recall = 0;
};

Scores score(const WoodSeparation& ws, const std::vector<std::uint8_t>& leaf) {
  std::size_t tp = 0, pred = 0, truth = 0, leaves = 0, leaves_found = 0;
  for (std::size_t i = 0; i < leaf.size(); ++i) {
    truth += !leaf[i];
    pred += ws.wood[i];
    tp += ws.wood[i] && !leaf[i];
    leaves += leaf[i];
    leaves_found += leaf[i] && !ws.wood[i];
  }
  return {double(tp) / double(pred), double(tp) / double(truth),
          double(leaves_found) / double(leaves)};
}

PointCloud cloud_of(const std::vector<Vec3f>& pts) {
  PointCloud c;
  c.positions = pts;
  c.source = "test";
  return c;
}

}  // namespace

TEST_CASE("wood separation: bark-only scans of the grammar trees keep their wood", "[wood]") {
  for (const char* name : {"broadleaf", "conifer", "weeping"}) {
    for (std::uint64_t seed : {1, 2}) {
      const scanner::ScanResult s = scan(grow(name), false, seed);
      const WoodSeparation ws = separate_wood(s.cloud);
      std::size_t kept = 0;
      for (std::uint8_t w : ws.wood) kept += w;
      const double fraction = double(kept) / double(s.cloud.size());
      INFO(name << " seed " << seed << ": kept " << fraction << ", D " << ws.separation);
      CHECK(fraction >= 0.97);
      CHECK(ws.finite_points == s.cloud.size());
    }
  }
}

TEST_CASE("wood separation: most leaf returns of the leafy broadleaf scan are found", "[wood]") {
  const Skeleton t = grow("broadleaf");
  const scanner::ScanResult s = scan(t, true, 1, 3000);
  const std::vector<std::uint8_t> leaf = scanner::leaf_returns(t, s);
  REQUIRE(leaf.size() == s.cloud.size());
  const WoodSeparation ws = separate_wood(s.cloud);
  const Scores sc = score(ws, leaf);
  INFO("wood precision " << sc.wood_precision << ", wood recall " << sc.wood_recall
                         << ", leaf recall " << sc.leaf_recall << ", D " << ws.separation);
  CHECK(ws.leaf_mode);
  CHECK(ws.leaf_fraction > 0.5);
  // Without separation wood precision is the wood share of the scan (0.27).
  CHECK(sc.wood_precision >= 0.6);
  CHECK(sc.wood_recall >= 0.55);
  CHECK(sc.leaf_recall >= 0.75);
}

TEST_CASE("wood separation: the scanner labels leaf returns only when leaves are scanned",
          "[wood]") {
  const Skeleton t = grow("conifer");
  const scanner::ScanResult bark = scan(t, false);
  const std::vector<std::uint8_t> none = scanner::leaf_returns(t, bark);
  CHECK(std::count(none.begin(), none.end(), 1) == 0);
  const scanner::ScanResult leafy = scan(t, true);
  const std::vector<std::uint8_t> some = scanner::leaf_returns(t, leafy);
  const double share = double(std::count(some.begin(), some.end(), 1)) / double(some.size());
  CHECK(share > 0.3);
  CHECK(share < 0.9);
}

TEST_CASE("wood separation: the same cloud gives the same bytes", "[wood]") {
  const scanner::ScanResult s = scan(grow("broadleaf"), true);
  const WoodSeparation a = separate_wood(s.cloud), b = separate_wood(s.cloud);
  REQUIRE(a.wood == b.wood);
  REQUIRE(a.leaf_score.size() == b.leaf_score.size());
  CHECK(std::memcmp(a.leaf_score.data(), b.leaf_score.data(),
                    a.leaf_score.size() * sizeof(float)) == 0);
  CHECK(a.threshold == b.threshold);
  CHECK(a.separation == b.separation);
}

TEST_CASE("wood separation: bad input gives an error or all wood, never a crash", "[wood]") {
  CHECK_THROWS_AS(separate_wood(PointCloud{}), WoodError);

  const WoodSeparation one = separate_wood(cloud_of({{1, 2, 3}}));
  CHECK(one.wood == std::vector<std::uint8_t>{1});
  CHECK(one.leaf_points == 0);
  CHECK(!one.notes.empty());

  const WoodSeparation dup = separate_wood(cloud_of(std::vector<Vec3f>(500, {1, 1, 1})));
  CHECK(std::count(dup.wood.begin(), dup.wood.end(), 1) == 500);

  // Non-finite points (readers drop them by default; a caller may not) are neither wood nor
  // counted.
  std::vector<Vec3f> pts;
  for (int i = 0; i < 200; ++i) pts.push_back({0.01f * float(i), 0, 0.02f * float(i)});
  pts.push_back({NAN, 0, 0});
  pts.push_back({0, INFINITY, 0});
  const WoodSeparation nan = separate_wood(cloud_of(pts));
  CHECK(nan.finite_points == 200);
  CHECK(nan.wood[200] == 0);
  CHECK(nan.wood[201] == 0);
  CHECK(std::count(nan.wood.begin(), nan.wood.end(), 1) == 200);  // a line: wood

  // All points on one plane (a wall or the ground alone): one mode, all wood.
  std::vector<Vec3f> plane;
  for (int i = 0; i < 60; ++i) {
    for (int j = 0; j < 60; ++j) plane.push_back({0.05f * float(i), 0.05f * float(j), 0});
  }
  const WoodSeparation flat = separate_wood(cloud_of(plane));
  CHECK(flat.leaf_points == 0);
}

TEST_CASE("wood separation: select_points keeps the chosen points and their channels", "[wood]") {
  PointCloud c = cloud_of({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}});
  c.intensity = {1, 2, 3};
  c.classification = {4, 5, 6};
  c.offset = {10, 20, 30};
  const PointCloud s = select_points(c, {1, 0, 1});
  REQUIRE(s.size() == 2);
  CHECK(s.positions[1].x == 2);
  CHECK(s.intensity == std::vector<float>{1, 3});
  CHECK(s.classification == std::vector<std::uint8_t>{4, 6});
  CHECK(s.offset == c.offset);
}

TEST_CASE("wood separation: real scans lose no trunk and stay one tree", "[wood]") {
  for (const char* file :
       {"adtree_tree1.xyz", "rtwig_cloud.txt", "plantscan3d_A3B4.asc", "adtree_ahn3_delft.xyz"}) {
    const PointCloud cloud = read_point_cloud(std::string(RAMUS_SHARED_DIR "/data/") + file);
    const WoodSeparation ws = separate_wood(cloud);
    INFO(file << ": leaf fraction " << ws.leaf_fraction << ", D " << ws.separation);
    // The lowest tenth of the scan (the trunk) stays wood.
    float lo = INFINITY, hi = -INFINITY;
    for (const Vec3f& p : cloud.positions) lo = std::min(lo, p.z), hi = std::max(hi, p.z);
    std::size_t low = 0, low_wood = 0;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      if (cloud.positions[i].z > lo + 0.1f * (hi - lo)) continue;
      ++low, low_wood += ws.wood[i];
    }
    CHECK(double(low_wood) / double(low) >= 0.9);
    ReconstructOptions o;
    o.leaves_in_scan = LeafHandling::kAuto;
    CHECK(reconstruct(cloud, o).trees.size() == 1);
  }
}

TEST_CASE("wood separation: reconstruct with the leaves removed maps every input point", "[wood]") {
  const scanner::ScanResult s = scan(grow("broadleaf"), true, 1, 3000);
  ReconstructOptions o;
  o.leaves_in_scan = LeafHandling::kRemove;
  const ReconstructResult r = reconstruct(s.cloud, o);
  REQUIRE(r.trees.size() == 1);
  REQUIRE(r.point_tree.size() == s.cloud.size());
  const WoodSeparation ws = separate_wood(s.cloud);
  std::size_t in_tree = 0;
  for (std::size_t i = 0; i < ws.wood.size(); ++i) {
    if (!ws.wood[i]) CHECK(r.point_tree[i] == ReconstructResult::kNoTree);
    in_tree += r.point_tree[i] == 0;
  }
  CHECK(in_tree > 0);
  REQUIRE(!r.notes.empty());
  CHECK(r.notes.front().find("wood/leaf separation") != std::string::npos);
  // auto removes them too (a foliage mode, far above a quarter of the points, a fine scan).
  o.leaves_in_scan = LeafHandling::kAuto;
  CHECK(reconstruct(s.cloud, o).point_tree == r.point_tree);
}
