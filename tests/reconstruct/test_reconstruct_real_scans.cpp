// Every readable real scan in ../shared/data/ reconstructs into one valid skeleton, and the spruce
// among them onto its trunk.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "formats/point_cloud_io.h"
#include "reconstruct/reconstruct.h"

using namespace ramus;

TEST_CASE("reconstruct real scans: every readable scan gives one valid skeleton", "[reconstruct]") {
  const std::filesystem::path dir = std::filesystem::path(RAMUS_SHARED_DIR) / "data";
  if (!std::filesystem::exists(dir)) return;  // the shared data is not part of every checkout
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    const std::string ext = e.path().extension().string();
    if (ext == ".xyz" || ext == ".txt" || ext == ".asc" || ext == ".las") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  REQUIRE(files.size() >= 4);
  for (const auto& f : files) {
    INFO(f.string());
    const PointCloud cloud = read_point_cloud(f.string());
    ReconstructOptions o;
    o.leaves = false;
    const ReconstructResult r = reconstruct(cloud, o);
    // Every readable scan there holds one tree (SOURCES.md; adtree_ahn3_delft.xyz is one tree
    // from airborne LiDAR): the base finder must not split it.
    REQUIRE(r.trees.size() == 1);
    for (const Skeleton& s : r.trees) {
      CHECK(s.validate().empty());
      CHECK(s.size() >= 5);
      // The skeleton lies within the cloud's bounds (world coordinates).
      Vec3 lo, hi;
      s.bounds(lo, hi);
      CHECK(lo.z >= cloud.offset.z - 100);
    }
  }
}

// The lowest layer of a scan is ground only where it is a wide flat surface (ground_surface.h).
// Two bundled scans have none: plantscan3d_A3B4 is one branch, and at the foot of pytlidar_tree_1
// the scan ends in the flare of its trunk. The rule that took every point within the band above
// each cell's lowest point removed 702 and 716 of their points, the branch's lowest shoots and
// one side of the flare; now none.
TEST_CASE("reconstruct real scans: scans without ground lose no points as terrain",
          "[reconstruct]") {
  for (const char* name : {"plantscan3d_A3B4.asc", "pytlidar_tree_1.las"}) {
    const std::filesystem::path file = std::filesystem::path(RAMUS_SHARED_DIR) / "data" / name;
    if (!std::filesystem::exists(file)) continue;  // the shared data is not in every checkout
    INFO(name);
    ReconstructOptions o;
    o.leaves = false;
    const ReconstructResult r = reconstruct(read_point_cloud(file.string()), o);
    REQUIRE(r.trees.size() == 1);
    CHECK(r.counts.terrain_points == 0);
  }
}

// treels_spruce: a 17 m spruce whose trunk (a 0.13 m bark ring near the ground) stands in a skirt
// of branches 2.2 m wide. One algebraic circle through the base slab measured 0.62 m, which
// scaled every radius 4.6 x and made the mesh a column of cones, and the BSG's trunk chain
// wandered up to 0.8 m from the trunk between 2 and 8 m. Measured now: 0.134 m, and the heaviest
// chain within 0.033 m of its median line there, its root on that line (docs/reconstruction.md,
// Deviations and Centre lines, step 7).
TEST_CASE("reconstruct real scans: treels_spruce stands on a straight trunk of its own radius",
          "[reconstruct]") {
  const std::filesystem::path file =
      std::filesystem::path(RAMUS_SHARED_DIR) / "data" / "treels_spruce.laz";
  if (!std::filesystem::exists(file)) return;  // the shared data is not part of every checkout
  ReconstructOptions o;
  o.leaves = false;
  const ReconstructResult r = reconstruct(read_point_cloud(file.string()), o);
  REQUIRE(r.trees.size() == 1);
  const Skeleton& s = r.trees.front();
  CHECK(s.nodes[0].radius > 0.10);
  CHECK(s.nodes[0].radius < 0.18);
  // The root's heaviest chain between 2 and 8 m above the base.
  std::vector<std::size_t> size(s.size(), 1);
  for (std::size_t v = s.size(); v-- > 1;) size[std::size_t(s.nodes[v].parent)] += size[v];
  std::vector<std::vector<std::size_t>> children(s.size());
  for (std::size_t v = 1; v < s.size(); ++v) children[std::size_t(s.nodes[v].parent)].push_back(v);
  std::vector<Vec3> trunk;
  for (std::size_t v = 0; !children[v].empty();) {
    v = *std::max_element(children[v].begin(), children[v].end(),
                          [&](std::size_t a, std::size_t b) { return size[a] < size[b]; });
    const double h = s.nodes[v].position.z - s.nodes[0].position.z;
    if (h >= 2 && h <= 8) trunk.push_back(s.nodes[v].position);
  }
  REQUIRE(trunk.size() >= 10);
  std::vector<double> xs, ys;
  for (const Vec3& p : trunk) xs.push_back(p.x), ys.push_back(p.y);
  std::sort(xs.begin(), xs.end());
  std::sort(ys.begin(), ys.end());
  const double mx = xs[xs.size() / 2], my = ys[ys.size() / 2];
  double farthest = 0;
  for (const Vec3& p : trunk) farthest = std::max(farthest, std::hypot(p.x - mx, p.y - my));
  INFO("trunk nodes " << trunk.size() << ", farthest from their median line " << farthest);
  CHECK(farthest < 0.1);
  // The root stands on the trunk (the base finder put it 0.4 m off, in the ground's clutter; the
  // trunk tracking carries the trunk down to it along the line of the base's nodes: measured
  // 0.027 m; 0.103 m along the direction of the base's last three radii).
  CHECK(std::hypot(s.nodes[0].position.x - mx, s.nodes[0].position.y - my) < 0.1);
}
