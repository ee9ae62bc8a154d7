// The bark textures a mesh wears: a tile set's tiles laid out as a random Wang tiling that wraps
// around (so the picture repeats seamlessly under REPEAT sampling and mipmaps like any power-of-
// two texture), and a normal map derived from it (height from luminance).
#pragma once

#include <cstdint>
#include <string>

#include "backends/texture/image.h"
#include "backends/texture/tile_atlas.h"
#include "backends/texture/tile_set.h"

namespace ramus::texture {

// A grid x grid tiling of the set's tiles in which every pair of neighbours, including the pairs
// across the wrap-around (last column next to the first, last row next to the first), shares its
// edge colour (Burkus 5.1: "any quad may be assigned one of the matching tiles at random"). The
// set is complete (every colour combination exists), so a tile always fits. grid >= 1.
Image wang_tiling(const TileSet& set, int grid, std::uint64_t seed);

// Tangent-space normals (glTF normalTexture: RGB = 0.5 + 0.5 n, +z out of the surface) of the
// height field given by the picture's luminance, wrapping at the borders; `strength` scales the
// slopes (height 1 per full luminance range over one pixel is strength 1).
Image normal_map(const Image& picture, double strength);

// Encoded pictures of a mesh's bark: base colour and normal map, JPEG (quality 90: bark is
// noisy, and PNG would make the textures several times the size of the geometry).
struct BarkTextures {
  std::string base;
  std::string normal;
  std::string height;  // the luminance as a grey picture (the bump map of OBJ's MTL)
  std::string mime = "image/jpeg";
};

// From a tile set atlas: a 4 x 4 Wang tiling of its tiles (1024 x 1024 for 256-pixel tiles).
BarkTextures bark_textures(const TileSet& set, std::uint64_t seed = 1);
// The textures of the bundled tile set (computed once per process).
const BarkTextures& bundled_bark_textures();

// Per-quad tiles (the pieces, Burkus 5.1): the set's padded atlas (tile_atlas.h, 8-pixel gutters
// per 256 pixels of tile) and its textures, base colour and normal map of the atlas itself.
TileAtlas bark_atlas(const TileSet& set);
BarkTextures bark_atlas_textures(const TileAtlas& atlas);
// The bundled set's (computed once per process).
const TileAtlas& bundled_bark_atlas();
const BarkTextures& bundled_bark_atlas_textures();

}  // namespace ramus::texture
