#include "backends/pieces/bark_tiles.h"

#include <cmath>
#include <map>
#include <numeric>

#include "backends/pieces/piece_build.h"
#include "backends/texture/tile_set.h"
#include "core/rng.h"

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

struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void join(std::uint32_t a, std::uint32_t b) { parent[find(a)] = find(b); }
};

std::vector<Trs> rest_world(const Tree& tree) {
  std::vector<Trs> world(tree.bones.size());
  for (std::size_t i = 0; i < tree.bones.size(); ++i) {
    const std::uint32_t p = tree.bones[i].parent;
    world[i] = p == kNone ? tree.pose[i] : world[p] * tree.pose[i];
  }
  return world;
}

}  // namespace

BarkTiling bark_tiling(const PieceSet& set, const Tree& tree, int edges, std::uint64_t seed) {
  std::vector<EdgeSides> sides(set.types.size());
  for (std::size_t t = 0; t < set.types.size(); ++t) sides[t] = edge_sides(set.types[t].lods[0]);
  std::vector<std::uint32_t> first(tree.pieces.size() + 1, 0);  // first slot (quad side) per piece
  for (std::size_t i = 0; i < tree.pieces.size(); ++i) {
    first[i + 1] =
        first[i] + 4 * std::uint32_t(set.types[tree.pieces[i].type].lods[0].quads.size());
  }
  auto slot = [&](std::size_t piece, const Side& s) { return first[piece] + 4 * s.quad + s.side; };
  BarkTiling out;
  UnionFind colours(first.back());
  // Inside every piece.
  for (std::size_t i = 0; i < tree.pieces.size(); ++i) {
    for (const auto& [edge, list] : sides[tree.pieces[i].type]) {
      if (list.size() != 2) continue;
      ++out.joins;
      if (regular(list[0], list[1], list[0].from == list[1].to)) {
        colours.join(slot(i, list[0]), slot(i, list[1]));
      } else {
        ++out.irregular_joins;
      }
    }
  }
  // Across joints: the child's root rim corner k lies on the parent's leaf rim corner k + twist;
  // the twist is found from the rest pose (fitted trees aim their joints, assembled ones twist).
  const std::vector<Trs> world = rest_world(tree);
  for (std::size_t i = 0; i < tree.pieces.size(); ++i) {
    const PlacedPiece& child = tree.pieces[i];
    if (child.parent == kNone) continue;
    const PlacedPiece& parent = tree.pieces[child.parent];
    const PieceType& ct = set.types[child.type];
    const PieceType& pt = set.types[parent.type];
    const Rim& leaf = pt.leaves.at(child.parent_leaf);
    const Trs& rim_world = world[parent.bone_offset + leaf.joint];
    const Trs& root_world = world[child.bone_offset + ct.root.joint];
    const Vec3 c0 = root_world.point(canonical_corner(0));
    int twist = 0;
    double best = 1e300;
    for (int j = 0; j < kRimCorners; ++j) {
      const double d = distance(rim_world.point(canonical_corner(j)), c0);
      if (d < best) best = d, twist = j;
    }
    for (int k = 0; k < kRimCorners; ++k) {
      const int j = (k + twist) % kRimCorners, k1 = (k + 1) % kRimCorners;
      const int j1 = (j + 1) % kRimCorners;
      const Side* cs = find_side(sides[child.type], ct.root.corners[k], ct.root.corners[k1]);
      const Side* ps = find_side(sides[parent.type], leaf.corners[j], leaf.corners[j1]);
      if (cs == nullptr || ps == nullptr) continue;
      ++out.joins;
      // Reversed: the child runs corner k -> k+1 while the parent runs j+1 -> j, or the other way.
      const bool child_forward = cs->from == ct.root.corners[k];
      const bool parent_forward = ps->from == leaf.corners[j];
      if (regular(*cs, *ps, child_forward != parent_forward)) {
        colours.join(slot(i, *cs), slot(child.parent, *ps));
      } else {
        ++out.irregular_joins;
      }
    }
  }
  // A colour per class of tied sides, then the tile with each quad's four colours.
  Rng rng = Rng::stream(seed, 0x6261726b);  // "bark"
  std::vector<int> colour(first.back(), -1);
  for (std::uint32_t s = 0; s < first.back(); ++s) {
    const std::uint32_t root = colours.find(s);
    if (colour[root] < 0) colour[root] = int(rng.below(std::uint64_t(edges)));
    colour[s] = colour[root];
  }
  texture::TileSet ids;
  ids.edges = edges;
  for (std::size_t i = 0; i < tree.pieces.size(); ++i) {
    const std::size_t quads = set.types[tree.pieces[i].type].lods[0].quads.size();
    std::vector<std::uint16_t> tiles(quads);
    for (std::size_t q = 0; q < quads; ++q) {
      const int* c = &colour[first[i] + 4 * q];  // sides south, east, north, west
      tiles[q] = std::uint16_t(ids.id_of({c[2], c[0], c[3], c[1]}));
    }
    out.tiles.push_back(std::move(tiles));
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
