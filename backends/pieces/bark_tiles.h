// Per-quad bark tiles of an assembled tree (Burkus et al. 2017, section 5.1): every base quad of
// every placed piece shows one tile of a Wang tile set (backends/texture/tile_set.h, K edge
// colours per direction), chosen so that any two quads sharing an edge show tiles whose touching
// edges have the same colour. As in 5.1 the rims, where pieces meet, have a fixed colour (0), so
// pieces join whatever their neighbours; inside a piece every edge draws a colour at random, the
// generalization 5.1 names ("any sets of tiles with any edge colorings, e.g. using the random
// tile placement described by Cohen et al."), and every quad takes the tile with its four colours
// (the set is complete, so one always exists). Each piece type gets a few such variants and each
// placed piece one of them at random, so instances differ while a glTF file needs only a few
// meshes per type (one per variant: the tiles live in the texture coordinates).
//
// A quad's corners a b c d (PieceMesh::quads) span its tile as south-west, south-east,
// north-east, north-west: edge a-b is the tile's south edge, b-c east, c-d north, d-a west. Two
// quads join regularly when the shared edge is one's north and the other's south (or east and
// west), traversed in opposite directions; only such joins can continue the tile pattern. The
// built-in pieces join regularly everywhere, across their rims too, except along the ridges of
// their forks (two quads meet south edge to south edge there), where the colours are drawn
// independently.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "backends/pieces/pieces.h"
#include "backends/texture/tile_atlas.h"

namespace ramus::pieces {

struct BarkTiling {
  // Per placed piece, per base quad: the tile id in the set's atlas (row * K^2 + column).
  std::vector<std::vector<std::uint16_t>> tiles;
  std::vector<std::uint32_t> variant;  // per placed piece: which of its type's variants
};

// The tiles for a set with `edges` colours per direction (1, 2 or 4): `variants` per piece type,
// one per placed piece, all from `seed`.
BarkTiling bark_tiling(const PieceSet& set, const Tree& tree, int edges, std::uint64_t seed,
                       int variants = 8);

// The joins of a base mesh whose sides are not tied (the ridges of forks and trifurcations).
std::size_t irregular_joins(const PieceMesh& base);

// Where corner `corner` (0..3) of quad `quad` of a level-of-detail mesh lies in its base quad's
// tile: (s, t) with s from west to east and t from north to south, 0..1 (a tessellated level
// splits every base quad into segments x segments quads, lod.cpp).
std::array<double, 2> tile_coords(const PieceMesh& mesh, std::size_t quad, int corner);

// The bark's texture coordinates (u, v per corner, 4 corners per quad, quad by quad) of a
// level-of-detail mesh whose base quads show `tiles` of `atlas`.
std::vector<float> bark_uvs(const PieceMesh& mesh, std::span<const std::uint16_t> tiles,
                            const texture::TileAtlas& atlas);

}  // namespace ramus::pieces
