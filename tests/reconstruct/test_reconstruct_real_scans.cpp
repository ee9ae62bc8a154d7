// Every readable real scan in ../shared/data/ reconstructs into one valid skeleton.
#include <catch2/catch.hpp>
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
