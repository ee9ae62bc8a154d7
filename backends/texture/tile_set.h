// Bark tile sets whose edges match (Burkus, Karpati & Szecsi, section 5.2; Cohen et al. 2003's
// Wang tiles): K edge colours for the horizontal edges and K for the vertical edges, one tile for
// every (north, south, west, east) colour choice, K^4 tiles in all. Each edge colour is a strip
// cut from an exemplar; a tile's outer band on each side is half of its edge colour's strip, so
// two tiles whose touching edges share a colour continue the same strip across the join. The
// inside of each tile is a patch of an exemplar stitched to the four bands with minimum-error
// boundary cuts (min_error_cut.h), as 5.2 stitches each photo with the four edge images. The
// corners are one shared corner patch, so four tiles meeting at a corner continue it too.
//
// The atlas puts tile (n, s, w, e) at grid row n*K + s and column w*K + e: a K^2 x K^2 grid of
// tile x tile pixels (1024 x 1024 for the default K = 2, tile 256: a power of two, so it mipmaps).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "backends/texture/image.h"

namespace ramus::texture {

struct TileSetOptions {
  int edges = 2;   // K, edge colours per direction: 1, 2 or 4
  int tile = 256;  // tile side in pixels: a power of two, 32..2048
  std::uint64_t seed = 1;
  bool straight_joins = false;  // join the pieces along straight lines instead of cuts (pictures)
};

// Edge colours of one tile.
struct TileEdges {
  int north = 0, south = 0, west = 0, east = 0;
};

struct TileSet {
  int edges = 0;
  int tile = 0;
  Image atlas;
  // Per atlas pixel, which piece it came from: 0 the corner patch, 1 an edge strip, 2 the tile's
  // inside. The boundaries between labels are the joins (seam pictures draw them).
  std::vector<std::uint8_t> source;

  int tiles_per_side() const { return edges * edges; }
  int count() const { return tiles_per_side() * tiles_per_side(); }
  // Tile id = row * K^2 + column in the atlas grid.
  TileEdges edges_of(int id) const;
  int id_of(const TileEdges& e) const;
  // The tile's pixels.
  Image tile_image(int id) const;
};

// Builds the set from the exemplars (at least one; each at least tile x tile pixels). Throws
// std::invalid_argument for bad options or too small exemplars. Same inputs and seed => same
// pixels.
TileSet build_tile_set(const std::vector<Image>& exemplars, const TileSetOptions& options);

// The exemplar of the bundled set (bark_exemplar.h at 1024 x 1024) and the set built from it.
Image bundled_bark_exemplar();
TileSet bundled_tile_set(const TileSetOptions& options = {});

// The atlas with the joins between corner patch, edge strips and insides drawn in red, and the
// tile borders in dark grey: the picture that shows where the cuts ran.
Image highlight_joins(const TileSet& set);

// The set a tile set atlas holds (as `ramus tiles` writes it) for K = `edges`; throws
// std::invalid_argument when the picture cannot be such an atlas (not square, or its side not
// K^2 tiles of a power-of-two size from 32 to 2048). `source` is all 2 (the joins are unknown).
TileSet tile_set_from_atlas(Image atlas, int edges);

// Checks that an atlas of `width` x `height` can hold a set of K edges and tiles of `tile`
// pixels; returns the message for a mismatch, empty if it fits.
std::string atlas_mismatch(int width, int height, int edges, int tile);

}  // namespace ramus::texture
