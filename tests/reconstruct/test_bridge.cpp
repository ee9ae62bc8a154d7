// Bridging the gaps between graph components (reconstruct/bsg/bridge.h).
#include <algorithm>
#include <catch2/catch.hpp>

#include "reconstruct/bsg/bridge.h"
#include "reconstruct/bsg/forest.h"
#include "reconstruct/bsg/graph.h"

using namespace ramus::bsg;

namespace {

bool linked(const Graph& g, std::uint32_t u, std::uint32_t v) {
  return std::any_of(g.adj[u].begin(), g.adj[u].end(), [&](const Arc& a) { return a.to == v; });
}

// The graph of `pts` merged on voxels of `voxel`, each vertex linked to its k nearest; pv maps
// points to vertices, and the graph's component count goes to *count.
Graph graph_of(const std::vector<Eigen::Vector3d>& pts, double voxel, int k,
               std::vector<std::uint32_t>& pv, std::uint32_t* count) {
  Graph g = voxelize(pts, std::vector<std::uint8_t>(pts.size(), 1), voxel, pv);
  link_nearest(g, k);
  components(g, count);
  return g;
}

}  // namespace

TEST_CASE("reconstruct stages: gaps up to max_gap are bridged, farther ones are not",
          "[reconstruct]") {
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i < 5; ++i) pts.emplace_back(0.1 * i, 0, 0);
  for (int i = 0; i < 5; ++i) pts.emplace_back(1.0 + 0.1 * i, 0, 0);  // gap of 0.6
  for (int i = 0; i < 5; ++i) pts.emplace_back(5.0 + 0.1 * i, 0, 0);  // gap of 3.6
  std::vector<std::uint32_t> pv;
  std::uint32_t n = 0;
  Graph g = graph_of(pts, 0.05, 2, pv, &n);
  REQUIRE(n == 3);
  CHECK(bridge_gaps(g, {pv[0]}, 1.0) == 1);
  const Forest f = shortest_path_forest(g, {pv[0]});
  CHECK(f.tree[pv[9]] == 0);
  CHECK(f.tree[pv[10]] == kNone);
}

TEST_CASE(
    "reconstruct stages: a branch fragment is bridged along its axis, not to the nearest bark",
    "[reconstruct]") {
  // Reached from the root at the origin: a stem along x up to x = 1, and (through a short
  // connector along y) a neighbouring branch parallel to it at y = 0.25 that runs on to x = 2.
  // The fragment, x = 1.5 .. 2 on the stem's line, is 0.25 from the neighbour's bark but 0.5
  // from its own stem's end.
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i <= 20; ++i) pts.emplace_back(0.05 * i, 0, 0);     // stem, 0 .. 20
  for (int i = 1; i <= 5; ++i) pts.emplace_back(0, 0.05 * i, 0);      // connector
  for (int i = 1; i <= 40; ++i) pts.emplace_back(0.05 * i, 0.25, 0);  // neighbour
  const std::size_t first = pts.size();
  for (int i = 0; i <= 10; ++i) pts.emplace_back(1.5 + 0.05 * i, 0, 0);  // fragment
  std::vector<std::uint32_t> pv;
  std::uint32_t n = 0;
  Graph g = graph_of(pts, 0.02, 4, pv, &n);
  REQUIRE(n == 2);
  Graph nearest_only = g;
  BridgeParams p;
  p.max_gap = 1.0;
  CHECK(bridge_gaps(g, {pv[0]}, p) == 1);
  CHECK(linked(g, pv[first], pv[20]));  // fragment end -> stem end, along the axis
  // Without the preference the nearest bark wins.
  p.off_axis_penalty = 1.0;
  p.cone_degrees = 1e-3;
  CHECK(bridge_gaps(nearest_only, {pv[0]}, p) == 1);
  CHECK_FALSE(linked(nearest_only, pv[first], pv[20]));
  const Forest f = shortest_path_forest(g, {pv[0]});
  CHECK(f.tree[pv[first + 10]] == 0);
}

TEST_CASE("reconstruct stages: a long fragment beyond max_gap is bridged once nothing else can be",
          "[reconstruct]") {
  // A stem x = 0 .. 0.4 from the root; a small fragment 0.9 beyond it; a long fragment (a limb
  // seen only beyond the stem it leaves) 0.5 beyond the small one and 1.6 beyond the stem; a short
  // fragment 1.9 before the stem.
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i < 5; ++i) pts.emplace_back(0.1 * i, 0, 0);         // stem, 0 .. 4
  for (int i = 0; i < 3; ++i) pts.emplace_back(1.3 + 0.1 * i, 0, 0);   // small, 5 .. 7
  for (int i = 0; i < 7; ++i) pts.emplace_back(2.0 + 0.1 * i, 0, 0);   // long, 8 .. 14
  for (int i = 0; i < 3; ++i) pts.emplace_back(-1.9 - 0.1 * i, 0, 0);  // short, far: 15 .. 17
  std::vector<std::uint32_t> pv;
  std::uint32_t n = 0;
  Graph g = graph_of(pts, 0.05, 2, pv, &n);
  REQUIRE(n == 4);
  BridgeParams p;
  p.max_gap = 1.0;
  p.hidden_limb_gap = 2.0;
  p.hidden_limb_length = 0.5;
  CHECK(bridge_gaps(g, {pv[0]}, p) == 2);
  CHECK(linked(g, pv[8], pv[7]));  // through the small fragment, not 1.6 to the stem
  CHECK_FALSE(linked(g, pv[8], pv[4]));
  const Forest f = shortest_path_forest(g, {pv[0]});
  CHECK(f.tree[pv[14]] == 0);
  CHECK(f.tree[pv[15]] == kNone);  // too short to reach farther than max_gap
  // Without the small fragment the long one hangs from the stem, 1.6 away; with max_gap alone
  // it is lost.
  std::vector<Eigen::Vector3d> two(pts.begin(), pts.begin() + 5);
  two.insert(two.end(), pts.begin() + 8, pts.begin() + 15);
  Graph h = graph_of(two, 0.05, 2, pv, &n);
  REQUIRE(n == 2);
  Graph without = h;
  CHECK(bridge_gaps(h, {pv[0]}, p) == 1);
  CHECK(linked(h, pv[5], pv[4]));
  CHECK(bridge_gaps(without, {pv[0]}, 1.0) == 0);
}
