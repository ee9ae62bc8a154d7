// Texture tiles (Burkus et al. 2017, section 5.1): every quad accepts the tiles of its type (1 on
// tubes, 2 near forks; the type is set when the piece is built), and every piece instance draws
// one of them per quad, so instances of one piece type look different. The draw is a texture-array
// slice: type 1's tiles come first, then type 2's.
#include "backends/pieces/pieces.h"
#include "formats/rmb/rmb_piece_stream_expand.h"

namespace ramus::pieces {

std::vector<std::uint16_t> assign_tiles(const PieceMesh& base, const TileOptions& options,
                                        std::uint64_t seed, std::uint32_t placed) {
  // The draw the expansion of an .rmb's placed-pieces stream makes too (one code for both).
  return draw_piece_tiles(base.quads.size(), base.quad_tile_type, options.tiles_per_type, seed,
                          placed);
}

Forest pose_copies(const PieceSet& set, const Tree& tree, int copies, std::uint64_t seed,
                   double spacing, const TileOptions& tiles) {
  Forest f;
  for (int k = 0; k < copies; ++k) {
    Tree t = tree;
    if (k > 0) {
      t.pose = random_pose(t, t.pose, seed + std::uint64_t(k));
      for (std::size_t i = 0; i < t.pieces.size(); ++i) {
        t.pieces[i].tiles = assign_tiles(set.types[t.pieces[i].type].lods[0], tiles,
                                         seed + std::uint64_t(k), std::uint32_t(i));
      }
    }
    // Copies side by side along x: move the root bone (its translation is in the world frame).
    Vec3 shift{spacing * k, 0, 0};
    if (!t.bones.empty()) {
      t.pose[0].t += shift;
      t.bones[0].rest.t += shift;
      Mat4 move;
      move(0, 3) = shift.x;
      for (PlacedPiece& p : t.pieces) p.topological = move * p.topological;
    }
    f.trees.push_back(std::move(t));
  }
  return f;
}

}  // namespace ramus::pieces
