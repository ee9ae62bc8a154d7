#include "backends/texture/tile_set.h"

#include <algorithm>
#include <functional>
#include <stdexcept>
#include <string>

#include "backends/texture/bark_exemplar.h"
#include "backends/texture/min_error_cut.h"
#include "core/rng.h"

namespace ramus::texture {
namespace {

// Keys of the random streams, so every choice depends only on (seed, role, index).
enum Role : std::uint64_t { kCorner = 1, kHorizontal, kVertical, kInside };

// Candidate inside patches tried per tile: Efros & Freeman choose among patches whose overlap
// error is low; the best of a few random ones is their choice at a fixed cost.
constexpr int kInsideCandidates = 8;

Image transpose(const Image& in) {
  Image out(in.height, in.width);
  for (int y = 0; y < in.height; ++y) {
    for (int x = 0; x < in.width; ++x) std::copy_n(in.at(x, y), 3, out.at(y, x));
  }
  return out;
}

std::vector<std::uint8_t> transpose(const std::vector<std::uint8_t>& in, int w, int h) {
  std::vector<std::uint8_t> out(in.size());
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) out[std::size_t(x) * h + y] = in[std::size_t(y) * w + x];
  }
  return out;
}

Image random_patch(const Image& from, int w, int h, Rng& rng) {
  const int x = int(rng.below(std::uint64_t(from.width - w + 1)));
  const int y = int(rng.below(std::uint64_t(from.height - h + 1)));
  return from.crop(x, y, w, h);
}

// Candidate edge patterns tried per edge colour.
constexpr int kEdgeCandidates = 32;

// Mean squared difference between the two middle columns (vertical = true) or rows of a patch:
// where two tiles meet, their pixels are those two lines of the edge pattern.
double join_line_error(const Image& p, bool vertical) {
  double sum = 0;
  const int n = vertical ? p.height : p.width;
  for (int i = 0; i < n; ++i) {
    sum += vertical ? pixel_distance2(p.at(p.width / 2 - 1, i), p.at(p.width / 2, i))
                    : pixel_distance2(p.at(i, p.height / 2 - 1), p.at(i, p.height / 2));
  }
  return sum / n;
}

// An edge pattern (or the corner patch): of a few random patches, the one whose join lines are
// calmest. The exemplar's own difference between neighbouring pixels varies from place to place
// (a furrow's flank against a plate's middle); a join that runs through a calm place is no
// stronger than the tiles' inside, wherever the exemplar has such places.
Image calm_patch(const Image& from, int w, int h, bool rows, bool columns, Rng& rng) {
  Image best;
  double best_error = 0;
  for (int c = 0; c < kEdgeCandidates; ++c) {
    Image p = random_patch(from, w, h, rng);
    const double e =
        (rows ? join_line_error(p, false) : 0) + (columns ? join_line_error(p, true) : 0);
    if (c == 0 || e < best_error) {
      best_error = e;
      best = std::move(p);
    }
  }
  return best;
}

// A labelled picture: the pixels and, per pixel, which piece they came from.
struct Labelled {
  Image image;
  std::vector<std::uint8_t> source;
};

// The strip of one horizontal edge colour, 2b rows by T columns: the shared corner patch's
// middle rows at both ends, the colour's own strip between, joined by cuts in the b columns next
// to each corner (the outer b columns stay pure corner, so the corner squares of all strips, both
// horizontal and vertical, hold the same pixels). Vertical strips are built as horizontal ones
// from the transposed pictures.
Labelled edge_strip(const Image& corner, const Image& strip, int b, bool straight) {
  const int t = strip.width, h = 2 * b;
  Labelled out{Image(t, h), std::vector<std::uint8_t>(std::size_t(t) * h, 1)};
  out.image.paste(strip, 0, 0);
  // Left join: across j runs from the corner side (x = b) inward; right join mirrors it.
  for (int side = 0; side < 2; ++side) {
    auto x_of = [&](int j) { return side == 0 ? b + j : t - b - 1 - j; };
    auto corner_px = [&](int x, int y) {
      return side == 0 ? corner.at(2 * b + x, b + y) : corner.at(x - (t - 2 * b), b + y);
    };
    std::vector<double> error(std::size_t(h) * b);
    for (int y = 0; y < h; ++y) {
      for (int j = 0; j < b; ++j) {
        error[std::size_t(y) * b + j] =
            pixel_distance2(corner_px(x_of(j), y), strip.at(x_of(j), y));
      }
    }
    std::vector<int> cut =
        straight ? std::vector<int>(std::size_t(h), b / 2) : min_error_cut(error, h, b, 0, b);
    for (int y = 0; y < h; ++y) {
      // Pure corner outside the band, then corner up to the cut.
      const int corner_width = b + cut[std::size_t(y)];
      for (int k = 0; k < corner_width; ++k) {
        const int x = side == 0 ? k : t - 1 - k;
        std::copy_n(corner_px(x, y), 3, out.image.at(x, y));
        out.source[std::size_t(y) * t + x] = 0;
      }
    }
  }
  return out;
}

Labelled transpose(const Labelled& l) {
  return {transpose(l.image), transpose(l.source, l.image.width, l.image.height)};
}

// One tile: the frame from the four strips' halves, the inside patch stitched to it by a cut in
// each side's band. The cut keeps at least `keep` frame pixels at the edge, so the pixels that
// touch the neighbouring tile always come from the shared strip.
struct Frame {
  Image image;
  std::vector<std::uint8_t> source;
};

// Applies one side's cut: (i, j) -> (x, y) maps step i along the side and depth j into the tile.
void stitch_side(Labelled& tile, const Frame& frame, const Image& inside, int b, int keep,
                 bool straight, const std::function<std::pair<int, int>(int, int)>& xy) {
  const int t = tile.image.width;
  std::vector<double> error(std::size_t(t) * b);
  for (int i = 0; i < t; ++i) {
    for (int j = 0; j < b; ++j) {
      auto [x, y] = xy(i, j);
      error[std::size_t(i) * b + j] = pixel_distance2(frame.image.at(x, y), inside.at(x, y));
    }
  }
  std::vector<int> cut =
      straight ? std::vector<int>(std::size_t(t), b / 2) : min_error_cut(error, t, b, keep, b);
  for (int i = 0; i < t; ++i) {
    for (int j = 0; j < cut[std::size_t(i)]; ++j) {
      auto [x, y] = xy(i, j);
      std::copy_n(frame.image.at(x, y), 3, tile.image.at(x, y));
      tile.source[std::size_t(y) * t + x] = frame.source[std::size_t(y) * t + x];
    }
  }
}

// The sum of the band errors of a candidate inside patch against the frame (for choosing it).
double band_error(const Frame& frame, const Image& inside, int b) {
  const int t = inside.width;
  double sum = 0;
  for (int y = 0; y < t; ++y) {
    for (int x = 0; x < t; ++x) {
      if (x < b || y < b || x >= t - b || y >= t - b) {
        sum += pixel_distance2(frame.image.at(x, y), inside.at(x, y));
      }
    }
  }
  return sum;
}

void check_options(const std::vector<Image>& exemplars, const TileSetOptions& o) {
  if (o.edges != 1 && o.edges != 2 && o.edges != 4) {
    throw std::invalid_argument(
        "edge colours must be 1, 2 or 4 (the atlas side is K^2 tiles, "
        "a power of two for mipmaps); got " +
        std::to_string(o.edges));
  }
  if (o.tile < 32 || o.tile > 2048 || (o.tile & (o.tile - 1)) != 0) {
    throw std::invalid_argument("the tile size must be a power of two from 32 to 2048; got " +
                                std::to_string(o.tile));
  }
  if (exemplars.empty()) throw std::invalid_argument("no exemplar pictures");
  for (std::size_t i = 0; i < exemplars.size(); ++i) {
    if (exemplars[i].width < o.tile || exemplars[i].height < o.tile) {
      throw std::invalid_argument("exemplar " + std::to_string(i + 1) + " is " +
                                  std::to_string(exemplars[i].width) + "x" +
                                  std::to_string(exemplars[i].height) + " pixels; tiles of " +
                                  std::to_string(o.tile) + " need exemplars at least that large");
    }
  }
}

}  // namespace

TileEdges TileSet::edges_of(int id) const {
  const int k = edges, row = id / tiles_per_side(), col = id % tiles_per_side();
  return {row / k, row % k, col / k, col % k};
}

int TileSet::id_of(const TileEdges& e) const {
  return (e.north * edges + e.south) * tiles_per_side() + e.west * edges + e.east;
}

Image TileSet::tile_image(int id) const {
  return atlas.crop((id % tiles_per_side()) * tile, (id / tiles_per_side()) * tile, tile, tile);
}

TileSet build_tile_set(const std::vector<Image>& exemplars, const TileSetOptions& o) {
  check_options(exemplars, o);
  const int t = o.tile, k = o.edges, b = t / 8, keep = std::max(2, b / 8);
  const std::size_t n = exemplars.size();
  Rng corner_rng = Rng::stream(o.seed, kCorner);
  const Image corner = calm_patch(exemplars[0], 4 * b, 4 * b, true, true, corner_rng);
  const Image corner_t = transpose(corner);
  std::vector<Labelled> horizontal, vertical;
  for (int c = 0; c < k; ++c) {
    Rng hr = Rng::stream(o.seed, kHorizontal, std::uint64_t(c));
    horizontal.push_back(
        edge_strip(corner, calm_patch(exemplars[std::size_t(c) % n], t, 2 * b, true, false, hr), b,
                   o.straight_joins));
    Rng vr = Rng::stream(o.seed, kVertical, std::uint64_t(c));
    Image v = calm_patch(exemplars[std::size_t(c + 1) % n], 2 * b, t, false, true, vr);
    vertical.push_back(transpose(edge_strip(corner_t, transpose(v), b, o.straight_joins)));
  }
  TileSet set;
  set.edges = k;
  set.tile = t;
  const int side = set.tiles_per_side() * t;
  set.atlas = Image(side, side);
  set.source.assign(std::size_t(side) * side, 2);
  for (int id = 0; id < set.count(); ++id) {
    const TileEdges e = set.edges_of(id);
    // The frame: the south half of the north strip on top, and so on.
    Frame frame{Image(t, t), std::vector<std::uint8_t>(std::size_t(t) * t, 2)};
    auto put = [&](const Labelled& from, int fx, int fy, int x, int y) {
      std::copy_n(from.image.at(fx, fy), 3, frame.image.at(x, y));
      frame.source[std::size_t(y) * t + x] = from.source[std::size_t(fy) * from.image.width + fx];
    };
    for (int y = 0; y < b; ++y) {
      for (int x = 0; x < t; ++x) {
        put(horizontal[std::size_t(e.north)], x, b + y, x, y);
        put(horizontal[std::size_t(e.south)], x, y, x, t - b + y);
      }
    }
    for (int y = 0; y < t; ++y) {
      for (int x = 0; x < b; ++x) {
        put(vertical[std::size_t(e.west)], b + x, y, x, y);
        put(vertical[std::size_t(e.east)], x, y, t - b + x, y);
      }
    }
    // The inside: the best of a few random patches of exemplar id mod n.
    Rng ir = Rng::stream(o.seed, kInside, std::uint64_t(id));
    const Image& from = exemplars[std::size_t(id) % n];
    Image inside;
    double best = 0;
    for (int c = 0; c < kInsideCandidates; ++c) {
      Image candidate = random_patch(from, t, t, ir);
      const double err = band_error(frame, candidate, b);
      if (c == 0 || err < best) {
        best = err;
        inside = std::move(candidate);
      }
    }
    Labelled tile{inside, std::vector<std::uint8_t>(std::size_t(t) * t, 2)};
    stitch_side(tile, frame, inside, b, keep, o.straight_joins, [](int i, int j) {
      return std::pair{i, j};
    });
    stitch_side(tile, frame, inside, b, keep, o.straight_joins, [t](int i, int j) {
      return std::pair{i, t - 1 - j};
    });
    stitch_side(tile, frame, inside, b, keep, o.straight_joins, [](int i, int j) {
      return std::pair{j, i};
    });
    stitch_side(tile, frame, inside, b, keep, o.straight_joins, [t](int i, int j) {
      return std::pair{t - 1 - j, i};
    });
    const int ox = (id % set.tiles_per_side()) * t, oy = (id / set.tiles_per_side()) * t;
    set.atlas.paste(tile.image, ox, oy);
    for (int y = 0; y < t; ++y) {
      std::copy_n(&tile.source[std::size_t(y) * t], t,
                  &set.source[std::size_t(oy + y) * side + ox]);
    }
  }
  return set;
}

Image bundled_bark_exemplar() { return bark_exemplar(1024, 1); }

TileSet bundled_tile_set(const TileSetOptions& options) {
  return build_tile_set({bundled_bark_exemplar()}, options);
}

Image highlight_joins(const TileSet& set) {
  Image out = set.atlas;
  const int side = out.width;
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      std::uint8_t* p = out.at(x, y);
      if (x % set.tile == 0 || y % set.tile == 0) {
        p[0] = p[1] = p[2] = 40;
        continue;
      }
      const std::uint8_t s = set.source[std::size_t(y) * side + x];
      const bool join = s != set.source[std::size_t(y) * side + x - 1] ||
                        s != set.source[std::size_t(y - 1) * side + x];
      if (join) {
        p[0] = 255;
        p[1] = 30;
        p[2] = 30;
      }
    }
  }
  return out;
}

TileSet tile_set_from_atlas(Image atlas, int edges) {
  if (edges != 1 && edges != 2 && edges != 4) {
    throw std::invalid_argument("edge colours must be 1, 2 or 4; got " + std::to_string(edges));
  }
  const int per_side = edges * edges, tile = atlas.width / per_side;
  if (atlas.width != atlas.height || atlas.width % per_side != 0 || tile < 32 || tile > 2048 ||
      (tile & (tile - 1)) != 0) {
    throw std::invalid_argument(
        "a tile set atlas of " + std::to_string(edges) + " edge colours is square with a side of " +
        std::to_string(per_side) + " power-of-two tiles (32..2048 pixels); this picture is " +
        std::to_string(atlas.width) + "x" + std::to_string(atlas.height));
  }
  TileSet set;
  set.edges = edges;
  set.tile = tile;
  set.source.assign(atlas.rgb.size() / 3, 2);
  set.atlas = std::move(atlas);
  return set;
}

std::string atlas_mismatch(int width, int height, int edges, int tile) {
  const int side = edges * edges * tile;
  if (width == side && height == side) return {};
  return "a tile set of " + std::to_string(edges) + " edge colours and " + std::to_string(tile) +
         "-pixel tiles is " + std::to_string(side) + "x" + std::to_string(side) +
         " pixels; this picture is " + std::to_string(width) + "x" + std::to_string(height);
}

}  // namespace ramus::texture
