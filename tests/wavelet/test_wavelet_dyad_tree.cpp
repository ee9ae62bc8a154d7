// Minimum spanning tree per dyad (III-E): infer/wavelet/dyad_tree.h.
#include <catch2/catch.hpp>
#include <cmath>

#include "infer/wavelet/dyad_tree.h"
#include "wavelet_fractal.h"

using namespace ramus;
using namespace ramus::wavelet;

TEST_CASE("dyad tree: nodes and root and Da Vinci areas and the skeleton on a fractal",
          "[wavelet]") {
  VoxelGrid g = test::sierpinski(5);
  g.voxel_size = 0.1;
  WaveletPyramid p = haar_forward(g, Decomposition::standard);
  std::vector<DyadTree> trees = dyad_trees(p);
  REQUIRE(trees.size() == 5);
  for (int j = 0; j < 5; ++j) {
    const DyadTree& t = trees[std::size_t(j)];
    INFO("dyad " << j);
    CHECK(t.size() == std::size_t(1) << (2 * j));  // 4^j occupied cells, all equally significant
    REQUIRE(t.root != kNoParent);
    CHECK(t.cells[t.root][2] == int(1u << j));  // the lowest cell of the dyad
    std::size_t roots = 0, leaves = 0;
    for (std::uint32_t u = 0; u < t.size(); ++u) {
      roots += t.parent[u] == kNoParent;
      bool leaf = true;
      for (std::uint32_t v = 0; v < t.size(); ++v) leaf = leaf && t.parent[v] != u;
      leaves += leaf ? 1 : 0;
      if (leaf) CHECK(t.leaves[u] == 1);
    }
    CHECK(roots == 1);
    if (t.size() > 1) CHECK(t.leaves[t.root] == leaves);
    Skeleton sk = to_skeleton(t, p);
    CHECK(sk.validate().empty());
    CHECK(sk.size() == t.size());
    for (std::size_t i = 1; i < sk.size(); ++i) CHECK(sk.nodes[i].parent < i);
    // Da Vinci: a node's area is the sum of its children's.
    auto ch = sk.children();
    for (std::uint32_t i = 0; i < sk.size(); ++i) {
      if (ch.count(i) == 0) continue;
      double sum = 0;
      for (const std::uint32_t* c = ch.begin(i); c != ch.end(i); ++c) {
        sum += std::pow(sk.nodes[*c].radius, 2);
      }
      CHECK(std::pow(sk.nodes[i].radius, 2) == Approx(sum));
    }
    // The skeleton is in the grid's frame: a cell of dyad j spans 32 / 2^j voxels of 0.1 m.
    double cell = 0.1 * 32 / double(1u << j);
    CHECK(sk.nodes[0].position.z == Approx(cell / 2));
    CHECK(t.length == Approx(sk.total_length() / cell));
  }
}

TEST_CASE("dyad tree: thresholds and empty dyads", "[wavelet]") {
  VoxelGrid g(3);
  g.at(1, 1, 1) = 1;
  g.at(6, 6, 6) = 1;
  WaveletPyramid p = haar_forward(g, Decomposition::nonstandard);
  DyadTreeOptions o;
  o.mode = ThresholdMode::absolute;
  o.threshold = 0.3;  // the finest details are 1/8: nothing passes
  DyadTree t = dyad_tree(p, 2, o);
  CHECK(t.root == kNoParent);
  CHECK(t.size() == 0);
  CHECK(to_skeleton(t, p).empty());
  o.threshold = 0.1;
  t = dyad_tree(p, 2, o);
  CHECK(t.size() == 2);
  CHECK(t.length == Approx(std::sqrt(27.0)));  // cells (0,0,0) and (3,3,3) of the 4^3 dyad
  CHECK(t.cells[t.root] == std::array<int, 3>{4, 4, 4});
  CHECK_THROWS_AS(dyad_tree(p, 3, o), std::out_of_range);
}

TEST_CASE("dyad tree: skeleton in world coordinates through the alignment", "[wavelet]") {
  VoxelGrid g(2);
  g.at(0, 0, 0) = 1;
  WaveletPyramid p = haar_forward(g, Decomposition::standard);
  DyadTree t = dyad_tree(p, 1);
  REQUIRE(t.size() == 1);
  Alignment a;
  a.root = {100, 200, 5};
  a.angle = 0;
  Skeleton sk = to_skeleton(t, p, {}, &a);
  REQUIRE(sk.size() == 1);
  // A cell of dyad 1 spans 2 voxels: its centre is 1 voxel from the corner.
  CHECK(sk.nodes[0].position.x == Approx(101));
  CHECK(sk.nodes[0].position.z == Approx(6));
}
