// Levels of detail (section 4.4): Phong tessellation of quads; tessellated rims of joined pieces
// match vertex for vertex at every LOD pairing, in the rest pose and posed.
#include "test_piece_support.h"

using namespace piece_test;

TEST_CASE("tessellated rims match vertex for vertex at every LOD pairing") {
  LowerPiecesOptions o;
  o.lod_segments = {1, 2, 3, 4, 8};
  PieceSet set = lower_text(kAlmond, o);
  REQUIRE(set.lod_segments == std::vector<int>{1, 2, 3, 4, 8});
  AssembleOptions ao;
  ao.seed = 4;
  Tree tree = assemble(set, ao);
  std::vector<Trs> posed = random_pose(tree, tree.pose, 77, 15);
  for (std::size_t a = 0; a < set.lod_segments.size(); ++a) {
    for (std::size_t b = 0; b < set.lod_segments.size(); ++b) {
      INFO("parent LOD " << a << ", child LOD " << b);
      // Levels that do not divide each other share only the corners; the rest share every
      // (fine / coarse)-th vertex of the finer loop.
      RimGap rest = rim_gaps(set, tree, tree.pose, a, b);
      RimGap pose = rim_gaps(set, tree, posed, a, b);
      int sa = set.lod_segments[a], sb = set.lod_segments[b];
      if (std::max(sa, sb) % std::min(sa, sb) != 0) continue;
      CHECK(rest.position < 1e-5);
      CHECK(rest.normal < 1e-5);
      CHECK(pose.position < 1e-5);
      CHECK(pose.normal < 1e-5);
    }
  }
}

TEST_CASE("Phong tessellation keeps base vertices, bulges edges along the normals") {
  PieceSet set = lower_text(kAlmond);
  const PieceType& I = set.types[0];
  const PieceMesh& base = I.lods[0];
  const PieceMesh& fine = I.lods[2];
  REQUIRE(fine.segments == 4);
  CHECK(fine.quads.size() == base.quads.size() * 16);
  // Vertices: base + 3 per edge + 9 per quad.
  std::size_t edges = base.quads.size() * 2;  // a closed-ring tube: two edges per quad, shared
  CHECK(fine.positions.size() == base.positions.size() + 3 * (edges + 6) + 9 * base.quads.size());
  for (std::size_t v = 0; v < base.positions.size(); ++v) {
    CHECK(fine.positions[v] == base.positions[v]);
  }
  // A rim edge's midpoint lies outside the straight chord (the hexagon rounds towards a circle)
  // and the loop has 6 * 4 vertices starting at corner 0.
  const auto& loop = fine.rim_loops[0];
  REQUIRE(loop.size() == 24);
  CHECK(loop[0] == I.root.corners[0]);
  CHECK(loop[4] == I.root.corners[1]);
  Vec3 mid = fine.positions[loop[2]];
  Vec3 chord = (base.positions[I.root.corners[0]] + base.positions[I.root.corners[1]]) * 0.5;
  CHECK(std::hypot(mid.x, mid.y) > std::hypot(chord.x, chord.y) + 0.01);
  CHECK(std::hypot(mid.x, mid.y) <
        1.05);  // Phong with alpha 3/4 overshoots a 60-degree arc slightly
  // Each fine quad keeps the tile type of the quad it came from.
  for (std::size_t q = 0; q < fine.quads.size(); ++q) {
    CHECK(fine.quad_tile_type[q] == base.quad_tile_type[fine.quad_source[q]]);
  }
}

TEST_CASE("an edge's new points do not depend on the order of its vertices") {
  PieceMesh a;
  a.positions = {{0, 0, 0}, {1, 0, 0.2}, {1, 1, 0}, {0, 1, 0.1}};
  a.normals = {normalized(Vec3{-0.3, -0.2, 1}), normalized(Vec3{0.4, -0.1, 1}),
               normalized(Vec3{0.2, 0.3, 1}), normalized(Vec3{-0.1, 0.5, 1})};
  a.uvs.assign(4, {0, 0});
  a.joints.assign(4, {0, 0, 0, 0});
  a.weights.assign(4, {1, 0, 0, 0});
  a.quads = {{0, 1, 2, 3}};
  a.quad_tile_type = {1};
  a.quad_source = {0};
  a.rim_loops = {{0, 1, 2, 3}};
  // The same quad with its vertices stored in another order.
  PieceMesh b = a;
  std::array<std::uint32_t, 4> perm{2, 3, 0, 1};
  for (int i = 0; i < 4; ++i) {
    b.positions[perm[i]] = a.positions[i];
    b.normals[perm[i]] = a.normals[i];
  }
  b.quads = {{perm[1], perm[2], perm[3], perm[0]}};
  b.rim_loops = {{perm[0], perm[1], perm[2], perm[3]}};
  PieceMesh ta = tessellate(a, 5), tb = tessellate(b, 5);
  REQUIRE(ta.rim_loops[0].size() == 20);
  for (std::size_t k = 0; k < 20; ++k) {
    CHECK(distance(ta.positions[ta.rim_loops[0][k]], tb.positions[tb.rim_loops[0][k]]) < 1e-14);
    CHECK(distance(ta.normals[ta.rim_loops[0][k]], tb.normals[tb.rim_loops[0][k]]) < 1e-14);
  }
}

TEST_CASE("run-time edge levels are symmetric and fall with distance") {
  Vec3 cam{0, -10, 2};
  Vec3 a{1, 2, 3}, b{1.5, 2.2, 3.1};
  for (double d = 0; d < 200; d += 7) {
    Vec3 s{d, 0, 0};
    CHECK(edge_tessellation_level(a + s, b + s, cam, 6, 5) ==
          edge_tessellation_level(b + s, a + s, cam, 6, 5));
  }
  CHECK(edge_tessellation_level(a, b, cam, 6, 20) == 6);
  CHECK(edge_tessellation_level(a + Vec3{0, 400, 0}, b + Vec3{0, 400, 0}, cam, 6, 20) ==
        2);  // 412 / 20 = 2^4.4: four levels less
  CHECK(edge_tessellation_level(a + Vec3{0, 1e6, 0}, b + Vec3{0, 1e6, 0}, cam, 6, 20) == 0);
}
