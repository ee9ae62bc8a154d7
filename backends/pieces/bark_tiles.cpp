#include "backends/pieces/bark_tiles.h"

#include <map>
#include <numeric>

#include "backends/texture/tile_set.h"
#include "core/rng.h"
#include "core/union_find.h"

namespace ramus::pieces {
namespace {

// Side s of a quad runs from its corner s to corner s + 1.
struct Side {
  std::uint32_t quad = 0;
  int side = 0;
  std::uint32_t from = 0, to = 0;  // base-mesh vertices, in the quad's order
};

// Every quad side of a piece type's base mesh, by undirected edge.
using EdgeSides = std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<Side>>;

EdgeSides edge_sides(const PieceMesh& m) {
  EdgeSides out;
  for (std::uint32_t q = 0; q < m.quads.size(); ++q) {
    for (int s = 0; s < 4; ++s) {
      const std::uint32_t a = m.quads[q][s], b = m.quads[q][(s + 1) % 4];
      out[{std::min(a, b), std::max(a, b)}].push_back({q, s, a, b});
    }
  }
  return out;
}

const Side* find_side(const EdgeSides& sides, std::uint32_t a, std::uint32_t b) {
  auto it = sides.find({std::min(a, b), std::max(a, b)});
  return it == sides.end() || it->second.size() != 1 ? nullptr : &it->second.front();
}

// Two sides continue each other's tiles when they are opposite sides (north-south, east-west)
// and run in opposite directions along the shared edge.
bool regular(const Side& x, const Side& y, bool reversed) {
  return y.side == (x.side + 2) % 4 && reversed;
}

}  // namespace

std::size_t irregular_joins(const PieceMesh& base) {
  std::size_t n = 0;
  for (const auto& [edge, list] : edge_sides(base))
    n += list.size() == 2 && !regular(list[0], list[1], list[0].from == list[1].to);
  return n;
}

BarkTiling bark_tiling(const PieceSet& set, const Tree& tree, int edges, std::uint64_t seed,
                       int variants) {
  texture::TileSet ids;
  ids.edges = edges;
  // Per piece type, its variants: the sides of its quads tied along regular joins, the rim
  // sides to colour 0, every other class of sides a colour of its own.
  std::vector<std::vector<std::vector<std::uint16_t>>> of_type(set.types.size());
  std::vector<char> used(set.types.size(), 0);
  for (const PlacedPiece& p : tree.pieces) used[p.type] = 1;
  for (std::uint32_t t = 0; t < set.types.size(); ++t) {
    if (!used[t]) continue;
    const PieceType& type = set.types[t];
    const PieceMesh& m = type.lods[0];
    const EdgeSides sides = edge_sides(m);
    UnionFind tied(4 * m.quads.size());
    auto slot = [](const Side& s) { return 4 * s.quad + std::uint32_t(s.side); };
    for (const auto& [edge, list] : sides) {
      if (list.size() == 2 && regular(list[0], list[1], list[0].from == list[1].to))
        tied.unite(slot(list[0]), slot(list[1]));
    }
    std::vector<char> on_rim(4 * m.quads.size(), 0);
    auto mark_rim = [&](const Rim& rim) {
      for (int k = 0; k < kRimCorners; ++k) {
        const Side* s = find_side(sides, rim.corners[k], rim.corners[(k + 1) % kRimCorners]);
        if (s != nullptr) on_rim[tied.find(slot(*s))] = 1;
      }
    };
    mark_rim(type.root);
    for (const Rim& rim : type.leaves) mark_rim(rim);
    for (int v = 0; v < variants; ++v) {
      Rng rng = Rng::stream(seed, t, 0x62617200u + std::uint64_t(v));  // "bar" + variant
      std::vector<int> colour(4 * m.quads.size(), -1);
      for (std::uint32_t s = 0; s < colour.size(); ++s) {
        const std::uint32_t root = tied.find(s);
        if (colour[root] < 0)
          colour[root] = on_rim[root] ? 0 : int(rng.below(std::uint64_t(edges)));
        colour[s] = colour[root];
      }
      std::vector<std::uint16_t> tiles(m.quads.size());
      for (std::size_t q = 0; q < tiles.size(); ++q) {
        const int* c = &colour[4 * q];  // sides south, east, north, west
        tiles[q] = std::uint16_t(ids.id_of({c[2], c[0], c[3], c[1]}));
      }
      of_type[t].push_back(std::move(tiles));
    }
  }
  BarkTiling out;
  Rng pick = Rng::stream(seed, 0x7069636b);  // "pick"
  for (const PlacedPiece& p : tree.pieces) {
    const std::uint32_t v = std::uint32_t(pick.below(std::uint64_t(variants)));
    out.variant.push_back(v);
    out.tiles.push_back(of_type[p.type][v]);
  }
  return out;
}

std::array<double, 2> tile_coords(const PieceMesh& mesh, std::size_t quad, int corner) {
  const int n = std::max(mesh.segments, 1);
  const std::size_t r = quad % std::size_t(n * n);
  const int i = int(r % std::size_t(n)) + (corner == 1 || corner == 2);
  const int j = int(r / std::size_t(n)) + (corner >= 2);
  return {double(i) / n, 1.0 - double(j) / n};
}

std::vector<float> bark_uvs(const PieceMesh& mesh, std::span<const std::uint16_t> tiles,
                            const texture::TileAtlas& atlas) {
  std::vector<float> uv;
  uv.reserve(mesh.quads.size() * 8);
  for (std::size_t q = 0; q < mesh.quads.size(); ++q) {
    const std::size_t base = q < mesh.quad_source.size() ? mesh.quad_source[q] : q;
    for (int k = 0; k < 4; ++k) {
      const std::array<double, 2> st = tile_coords(mesh, q, k);
      const std::array<float, 2> at = atlas.uv(tiles[base], st[0], st[1]);
      uv.insert(uv.end(), at.begin(), at.end());
    }
  }
  return uv;
}

}  // namespace ramus::pieces
