#include "backends/texture/bark_maps.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <stdexcept>

#include "core/rng.h"

namespace ramus::texture {

Image wang_tiling(const TileSet& set, int grid, std::uint64_t seed) {
  if (grid < 1) throw std::invalid_argument("wang_tiling: grid below 1");
  const int k = set.edges, t = set.tile;
  Rng rng = Rng::stream(seed, 0x77616e67);  // "wang"
  // Edge colours: horizontal[r][c] is the colour of the edge above cell (r, c) (row grid wraps
  // to row 0), vertical[r][c] the edge left of it. Drawing the edges, not the tiles, makes the
  // wrap-around match by construction; the tile of a cell is then the one with its four colours.
  std::vector<int> horizontal(std::size_t(grid) * grid), vertical(horizontal.size());
  for (int& c : horizontal) c = int(rng.below(std::uint64_t(k)));
  for (int& c : vertical) c = int(rng.below(std::uint64_t(k)));
  Image out(grid * t, grid * t);
  for (int r = 0; r < grid; ++r) {
    for (int c = 0; c < grid; ++c) {
      TileEdges e;
      e.north = horizontal[std::size_t(r) * grid + c];
      e.south = horizontal[std::size_t((r + 1) % grid) * grid + c];
      e.west = vertical[std::size_t(r) * grid + c];
      e.east = vertical[std::size_t(r) * grid + (c + 1) % grid];
      out.paste(set.tile_image(set.id_of(e)), c * t, r * t);
    }
  }
  return out;
}

Image normal_map(const Image& picture, double strength) {
  const int w = picture.width, h = picture.height;
  std::vector<double> height(std::size_t(w) * h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::uint8_t* p = picture.at(x, y);
      height[std::size_t(y) * w + x] = (0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]) / 255.0;
    }
  }
  auto at = [&](int x, int y) { return height[std::size_t((y + h) % h) * w + (x + w) % w]; };
  Image out(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      // Sobel slopes; image rows run top to bottom while glTF's v (and the tangent space's
      // bitangent) runs the other way, hence the sign of dy.
      const double dx = ((at(x + 1, y - 1) + 2 * at(x + 1, y) + at(x + 1, y + 1)) -
                         (at(x - 1, y - 1) + 2 * at(x - 1, y) + at(x - 1, y + 1))) /
                        8;
      const double dy = ((at(x - 1, y - 1) + 2 * at(x, y - 1) + at(x + 1, y - 1)) -
                         (at(x - 1, y + 1) + 2 * at(x, y + 1) + at(x + 1, y + 1))) /
                        8;
      double n[3] = {-strength * dx, -strength * dy, 1};
      const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      for (int c = 0; c < 3; ++c) {
        out.at(x, y)[c] =
            std::uint8_t(std::clamp(std::lround((0.5 + 0.5 * n[c] / len) * 255), 0L, 255L));
      }
    }
  }
  return out;
}

namespace {

BarkTextures textures_of(const Image& base) {
  // Bark furrows are deep next to the plates: slopes of a few luminance steps per pixel.
  Image grey(base.width, base.height);
  for (std::size_t i = 0; i < base.rgb.size(); i += 3) {
    const auto y = std::uint8_t(
        std::lround(0.2126 * base.rgb[i] + 0.7152 * base.rgb[i + 1] + 0.0722 * base.rgb[i + 2]));
    grey.rgb[i] = grey.rgb[i + 1] = grey.rgb[i + 2] = y;
  }
  return {encode_jpeg(base, 90), encode_jpeg(normal_map(base, 6.0), 90), encode_jpeg(grey, 90)};
}

}  // namespace

BarkTextures bark_textures(const TileSet& set, std::uint64_t seed) {
  return textures_of(wang_tiling(set, 4, seed));
}

TileAtlas bark_atlas(const TileSet& set) { return padded_atlas(set, std::max(2, set.tile / 32)); }

// The normal map's Sobel reads one pixel across a cell border only in the gutters.
BarkTextures bark_atlas_textures(const TileAtlas& atlas) { return textures_of(atlas.image); }

const TileAtlas& bundled_bark_atlas() {
  static std::once_flag once;
  static TileAtlas atlas;
  std::call_once(once, [] { atlas = bark_atlas(bundled_tile_set()); });
  return atlas;
}

const BarkTextures& bundled_bark_atlas_textures() {
  static std::once_flag once;
  static BarkTextures textures;
  std::call_once(once, [] { textures = bark_atlas_textures(bundled_bark_atlas()); });
  return textures;
}

const BarkTextures& bundled_bark_textures() {
  static std::once_flag once;
  static BarkTextures textures;
  std::call_once(once, [] { textures = bark_textures(bundled_tile_set()); });
  return textures;
}

}  // namespace ramus::texture
