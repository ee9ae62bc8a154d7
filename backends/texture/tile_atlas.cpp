#include "backends/texture/tile_atlas.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ramus::texture {
namespace {

// Bilinear sample of `img` at pixel-centre coordinates (x, y), clamped to the picture.
void sample(const Image& img, double x, double y, std::uint8_t* out) {
  x = std::clamp(x, 0.0, img.width - 1.0);
  y = std::clamp(y, 0.0, img.height - 1.0);
  const int x0 = std::min(int(x), img.width - 2 < 0 ? 0 : img.width - 2);
  const int y0 = std::min(int(y), img.height - 2 < 0 ? 0 : img.height - 2);
  const int x1 = std::min(x0 + 1, img.width - 1), y1 = std::min(y0 + 1, img.height - 1);
  const double fx = x - x0, fy = y - y0;
  for (int c = 0; c < 3; ++c) {
    const double top = img.at(x0, y0)[c] * (1 - fx) + img.at(x1, y0)[c] * fx;
    const double bottom = img.at(x0, y1)[c] * (1 - fx) + img.at(x1, y1)[c] * fx;
    out[c] = std::uint8_t(std::lround(std::clamp(top * (1 - fy) + bottom * fy, 0.0, 255.0)));
  }
}

}  // namespace

std::array<float, 2> TileAtlas::uv(int id, double s, double t) const {
  const int row = id / cells, col = id % cells;
  const double span = 1 - 2 * inset;
  return {float((col + inset + s * span) / cells), float((row + inset + t * span) / cells)};
}

TileAtlas padded_atlas(const TileSet& set, int gutter) {
  const int t = set.tile, n = set.tiles_per_side(), k = set.edges;
  if (gutter < 0 || 2 * gutter >= t) throw std::invalid_argument("padded_atlas: bad gutter");
  TileAtlas a;
  a.edges = k;
  a.cells = n;
  a.cell = t;
  a.inset = double(gutter) / (t + 2 * gutter);
  a.image = Image(n * t, n * t);
  for (int id = 0; id < set.count(); ++id) {
    // The tile in the middle of a 3 x 3 block of tiles that match it (the outer edges of the
    // block take colour 0): what a tiling shows around it.
    const TileEdges e = set.edges_of(id);
    const int north[3] = {0, e.north, e.south}, south[3] = {e.north, e.south, 0};
    const int west[3] = {0, e.west, e.east}, east[3] = {e.west, e.east, 0};
    const int side = t + 2 * gutter;
    Image padded(side, side);
    for (int by = 0; by < 3; ++by) {
      for (int bx = 0; bx < 3; ++bx) {
        const Image tile = set.tile_image(set.id_of({north[by], south[by], west[bx], east[bx]}));
        for (int y = 0; y < t; ++y) {
          const int py = (by - 1) * t + y + gutter;
          if (py < 0 || py >= side) continue;
          for (int x = 0; x < t; ++x) {
            const int px = (bx - 1) * t + x + gutter;
            if (px >= 0 && px < side) std::copy_n(tile.at(x, y), 3, padded.at(px, py));
          }
        }
      }
    }
    // Into the cell: (t + 2g) pixels onto t, pixel centres to pixel centres' positions.
    const double scale = double(side) / t;
    const int ox = (id % n) * t, oy = (id / n) * t;
    for (int y = 0; y < t; ++y) {
      for (int x = 0; x < t; ++x) {
        sample(padded, (x + 0.5) * scale - 0.5, (y + 0.5) * scale - 0.5,
               a.image.at(ox + x, oy + y));
      }
    }
  }
  return a;
}

}  // namespace ramus::texture
