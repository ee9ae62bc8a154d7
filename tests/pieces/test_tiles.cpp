// Texture tiles (section 5.1): a seeded tile per quad per instance, from the tiles of the quad's
// type, stored with the instance.
#include <set>

#include "test_piece_support.h"

using namespace piece_test;

TEST_CASE("each quad gets a tile of its own type, seeded per instance") {
  PieceSet set = lower_text(kAlmond);
  AssembleOptions o;
  o.seed = 21;
  o.tiles.tiles_per_type = {5, 3};
  Tree tree = assemble(set, o);
  std::set<int> used1, used2;
  for (const PlacedPiece& p : tree.pieces) {
    const PieceMesh& m = set.types[p.type].lods[0];
    REQUIRE(p.tiles.size() == m.quads.size());
    for (std::size_t q = 0; q < p.tiles.size(); ++q) {
      if (m.quad_tile_type[q] == 1) {
        CHECK(p.tiles[q] < 5);
        used1.insert(p.tiles[q]);
      } else {
        CHECK(p.tiles[q] >= 5);
        CHECK(p.tiles[q] < 8);
        used2.insert(p.tiles[q]);
      }
    }
  }
  CHECK(used1.size() == 5);
  CHECK(used2.size() == 3);
  // Two instances of one piece type do not share their tiling.
  std::size_t same = 0, pairs = 0;
  for (std::size_t i = 1; i < tree.pieces.size(); ++i) {
    for (std::size_t j = i + 1; j < tree.pieces.size(); ++j) {
      if (tree.pieces[i].type != tree.pieces[j].type) continue;
      ++pairs;
      same += tree.pieces[i].tiles == tree.pieces[j].tiles;
    }
  }
  CHECK(pairs > 10);
  CHECK(same == 0);
}

TEST_CASE("tiles are deterministic per seed and change with it") {
  PieceSet set = lower_text(kAlmond);
  const PieceMesh& m = set.types[1].lods[0];
  CHECK(assign_tiles(m, {}, 3, 7) == assign_tiles(m, {}, 3, 7));
  CHECK(assign_tiles(m, {}, 3, 7) != assign_tiles(m, {}, 4, 7));
  CHECK(assign_tiles(m, {}, 3, 7) != assign_tiles(m, {}, 3, 8));
  TileOptions one;
  one.tiles_per_type = {1, 1};
  for (std::size_t q = 0; q < m.quads.size(); ++q) {
    CHECK(assign_tiles(m, one, 3, 7)[q] == (m.quad_tile_type[q] == 1 ? 0 : 1));
  }
}
