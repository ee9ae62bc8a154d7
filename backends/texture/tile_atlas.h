// A tile set's atlas for per-quad texturing (Burkus 5.1: every quad shows one tile, chosen per
// quad): each tile sits in its own cell with a gutter around it, filled with what lies across
// each edge in a tiling (the other half of the edge colour's strip, and the corner patch at the
// corners, tile_set.h), so bilinear filtering and the first mip levels read bark that continues
// the tile instead of the next cell's unrelated tile. Cells keep the set's tile size, so the
// atlas stays the same power of two and every cell boundary lies on a pixel boundary down to
// mip level log2(tile): the tile plus its gutters, (tile + 2 g) pixels, is resampled into the
// tile-pixel cell.
#pragma once

#include <array>

#include "backends/texture/image.h"
#include "backends/texture/tile_set.h"

namespace ramus::texture {

struct TileAtlas {
  int edges = 0;     // K of the set
  int cells = 0;     // cells per side (K^2)
  int cell = 0;      // cell side in pixels (the set's tile size)
  double inset = 0;  // the tile's border inside its cell, as a fraction of the cell
  Image image;       // cells * cell pixels square
  // Texture coordinates (glTF: u right, v down, 0..1 over the atlas) of the point (s, t) of
  // tile `id`, s across it from west to east, t down it from north to south (0..1 each).
  std::array<float, 2> uv(int id, double s, double t) const;
};

// The atlas of `set` with gutters of `gutter` pixels (before resampling) around every tile.
TileAtlas padded_atlas(const TileSet& set, int gutter);

}  // namespace ramus::texture
