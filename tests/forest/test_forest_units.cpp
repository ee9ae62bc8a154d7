// Units of the forest-plot pipeline (docs/scale.md): trees joined and split, placement, the
// voxel thinning, the tile manifest, the core test and the detection score.
#include <catch2/catch.hpp>
#include <cmath>

#include "backends/scanner/forest.h"
#include "core/skeleton_trees.h"
#include "formats/point_cloud_io.h"
#include "formats/tile_manifest.h"
#include "formats/voxel_thin.h"
#include "reconstruct/forest/core_trees.h"
#include "reconstruct/forest/detection_score.h"

using namespace ramus;

namespace {

// A trunk of `height` at (x, y) with one branch.
Skeleton stick(double x, double y, double height = 5) {
  Skeleton s;
  SkeletonNode n;
  n.position = {x, y, 0};
  const std::uint32_t root = s.add(n);
  n.position = {x, y, height / 2};
  n.parent = root;
  const std::uint32_t mid = s.add(n);
  n.position = {x, y, height};
  n.parent = mid;
  s.add(n);
  n.position = {x + 1, y, height * 0.7};
  n.parent = mid;
  s.add(n);
  s.organs.push_back({mid, {x, y, height / 2}});
  return s;
}

}  // namespace

TEST_CASE("join_trees and split_trees are inverse", "[forest]") {
  const std::vector<Skeleton> trees{stick(0, 0), stick(5, 1, 7), stick(-3, 2)};
  const Skeleton forest = join_trees(trees);
  REQUIRE(forest.roots().size() == 3);
  REQUIRE(forest.validate().empty());
  const std::vector<Skeleton> back = split_trees(forest);
  REQUIRE(back.size() == 3);
  for (std::size_t t = 0; t < 3; ++t) {
    REQUIRE(back[t].nodes.size() == trees[t].nodes.size());
    REQUIRE(back[t].organs.size() == 1);
    CHECK(back[t].organs[0].node == trees[t].organs[0].node);
    for (std::size_t i = 0; i < back[t].nodes.size(); ++i) {
      CHECK(back[t].nodes[i].position == trees[t].nodes[i].position);
      CHECK(back[t].nodes[i].parent == trees[t].nodes[i].parent);
    }
  }
}

TEST_CASE("trees are placed a crown radius apart, the same for the same seed", "[forest]") {
  const std::vector<double> radii{3, 4, 2, 5, 3, 3};
  const scanner::PlotArea area{30, 30};
  const std::vector<Vec3> a = scanner::place_trees(radii, area, 7);
  REQUIRE(a == scanner::place_trees(radii, area, 7));
  CHECK(a != scanner::place_trees(radii, area, 8));
  for (std::size_t i = 0; i < a.size(); ++i) {
    CHECK(a[i].x >= 0);
    CHECK(a[i].x <= 30);
    for (std::size_t j = 0; j < i; ++j) {
      CHECK(std::hypot(a[i].x - a[j].x, a[i].y - a[j].y) >= std::max(radii[i], radii[j]));
    }
  }
  // Twenty trees of crown radius 5 do not fit in 10 x 10 m.
  REQUIRE_THROWS_WITH(scanner::place_trees(std::vector<double>(20, 5.0), {10, 10}, 1, 500),
                      Catch::Contains("finds no place") && Catch::Contains("--area"));
}

TEST_CASE("plant moves a tree's root to the ground at a place", "[forest]") {
  Skeleton s = stick(1, 2);
  for (auto& n : s.nodes) n.position.z += 3;
  const Skeleton p = scanner::plant(s, 10, 20);
  CHECK(p.nodes[0].position == Vec3{10, 20, 0});
  CHECK(p.nodes[3].position == Vec3{11, 20, 3.5});
  CHECK(scanner::crown_radius(p) == Approx(1));
}

TEST_CASE("voxel thinning keeps the first point of each cube", "[forest][thin]") {
  PointCloud c;
  c.positions = {{0.01f, 0.01f, 0.01f}, {0.02f, 0.03f, 0.04f}, {0.11f, 0, 0}, {-0.01f, 0, 0}};
  c.intensity = {1, 2, 3, 4};
  const PointCloud t = thin_cloud(c, 0.1);
  REQUIRE(t.size() == 3);
  CHECK(t.intensity == std::vector<float>{1, 3, 4});
  VoxelThinner v(0.5);
  CHECK(v.keep({0.1, 0.1, 0.1}));
  CHECK_FALSE(v.keep({0.4, 0.2, 0.3}));
  CHECK(v.keep({0.6, 0.2, 0.3}));
  CHECK(v.cells() == 2);
}

TEST_CASE("tile manifests round-trip and malformed ones name the place", "[forest][manifest]") {
  TileManifest m;
  m.size = 20;
  m.buffer = 6.5;
  m.sources = {"plot \"a\".las"};
  m.tiles.push_back({0, {0, 0, 20, 20}, {-6.5, -6.5, 26.5, 26.5}, "0.las", 1234});
  m.tiles.push_back({1, {20, 0, 40, 20}, {13.5, -6.5, 46.5, 26.5}, "1.las", 99});
  const std::string text = tile_manifest_to_json(m);
  const TileManifest back = tile_manifest_from_json(text, "m.json");
  REQUIRE(back.tiles.size() == 2);
  CHECK(back.sources == m.sources);
  CHECK(back.buffer == 6.5);
  CHECK(back.tiles[1].buffered.x0 == 13.5);
  CHECK(back.tiles[1].points == 99);
  CHECK(tile_manifest_to_json(back) == text);
  std::string bad = text;
  bad.replace(bad.find("\"id\": 1"), 7, "\"id\": 5");
  REQUIRE_THROWS_WITH(tile_manifest_from_json(bad, "m.json"),
                      Catch::Contains("m.json: line") && Catch::Contains("tiles[1].id"));
  bad = text;
  bad.replace(bad.find("\"core\": [0, 0, 20, 20]"), 22, "\"core\": [0, 0, 40, 20]");
  REQUIRE_THROWS_WITH(tile_manifest_from_json(bad, "m.json"),
                      Catch::Contains("inside the buffered"));
  REQUIRE_THROWS_WITH(tile_manifest_from_json("{\"format\": \"ramus-tiles\"}", "m.json"),
                      Catch::Contains("version"));
}

TEST_CASE("a tile keeps the trees based in its core and flags those at the buffer's edge",
          "[forest][tile]") {
  const forest::GroundBox core{0, 0, 10, 10}, buffered{-5, -5, 15, 15}, data{-20, -20, 40, 40};
  // Based inside; based on the far edge (belongs to the next tile); based outside; inside but
  // reaching past x = 15 - margin.
  Skeleton wide = stick(9, 5);
  wide.nodes[3].position.x = 14.99;
  const forest::CoreTrees kept = forest::keep_core_trees(
      {stick(1, 1), stick(10, 5), stick(-2, 3), wide}, core, buffered, data, 0.05);
  REQUIRE(kept.kept.size() == 2);
  CHECK(kept.kept[0].nodes[0].position.x == 1);
  REQUIRE(kept.touching == std::vector<std::size_t>{1});
  // The same edge where no data lies beyond is not a cut.
  const forest::CoreTrees edge =
      forest::keep_core_trees({wide}, core, buffered, {-20, -20, 15, 40}, 0.05);
  CHECK(edge.touching.empty());
}

TEST_CASE("detection scores match, miss, merge and split trees", "[forest][score]") {
  const std::vector<Skeleton> truth{stick(0, 0), stick(10, 0), stick(20, 0), stick(30, 0)};
  // Tree 0 found 0.2 m off; tree 1 found; tree 2 missed: its wood went to tree 1's detection
  // (merged); tree 3 found, plus a piece of its crown as a tree of its own (split); and a tree
  // where there is none (false).
  Skeleton merged = stick(10, 0);
  Skeleton piece = stick(20, 0);
  const Skeleton joint = join_trees({merged, piece});
  Skeleton one;  // tree 1 and tree 2's nodes under one root
  one.nodes = joint.nodes;
  one.nodes[4].parent = 0;
  Skeleton split_piece;
  SkeletonNode n;
  n.position = {31, 0, 3.5};  // truth tree 3's branch tip, 1 m from its base
  split_piece.add(n);
  n.position = {30, 0, 5};
  n.parent = 0;
  split_piece.add(n);
  const std::vector<Skeleton> detected{stick(0.2, 0), one, stick(30, 0), split_piece,
                                       stick(50, 50)};
  const forest::DetectionScore s = forest::score_detection(truth, detected);
  CHECK(s.matched == 3);
  CHECK(s.merged == 1);
  CHECK(s.missed == 0);
  CHECK(s.split == 1);
  CHECK(s.false_trees == 1);
  CHECK(s.max_base_error == Approx(0.2));
  CHECK(s.recall == Approx(0.75));
  CHECK(s.precision == Approx(0.6));
  CHECK(s.f_score == Approx(2 * 0.75 * 0.6 / 1.35));
}
