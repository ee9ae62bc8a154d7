// Per-quad bark tiles (bark_tiles.h, Burkus et al. 5.1) and the foliage anchors (foliage.h).
// The seam test looks at the bark as a renderer would: on every edge two quads share, in the
// tree's world, it samples the atlas just inside each quad at the same points of the edge and
// compares the two sides with neighbouring pixels inside one tile. Tiles drawn at random,
// ignoring the edge colours, show the seams the measure is there to catch.
#include <cmath>
#include <map>
#include <set>

#include "backends/pieces/bark_tiles.h"
#include "backends/pieces/foliage.h"
#include "backends/texture/bark_maps.h"
#include "core/rng.h"
#include "test_piece_support.h"

using namespace piece_test;

namespace {

// Bilinear sample of the atlas at texture coordinates (u, v).
std::array<double, 3> sample(const texture::Image& img, double u, double v) {
  const double x = std::clamp(u * img.width - 0.5, 0.0, img.width - 1.001);
  const double y = std::clamp(v * img.height - 0.5, 0.0, img.height - 1.001);
  const int x0 = int(x), y0 = int(y);
  const double fx = x - x0, fy = y - y0;
  std::array<double, 3> out{};
  for (int c = 0; c < 3; ++c) {
    out[c] = (img.at(x0, y0)[c] * (1 - fx) + img.at(x0 + 1, y0)[c] * fx) * (1 - fy) +
             (img.at(x0, y0 + 1)[c] * (1 - fx) + img.at(x0 + 1, y0 + 1)[c] * fx) * fy;
  }
  return out;
}

double difference(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return (std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2])) / 3;
}

struct SideRef {
  std::uint32_t piece, quad;
  int side;
  bool forward;  // runs from the edge's first end (by key order) to its second
};

struct SeamNumbers {
  double seam = 0;    // mean difference across regular joins
  double inside = 0;  // mean difference between the same two pixel rows inside the tiles
  double irregular = 0;
  std::size_t regular_joins = 0, irregular_joins = 0;
  std::size_t ridges = 0;  // irregular joins along the ridge of a fork or trifurcation
};

// Measures the joins of `tiles` (per piece, per base quad) on the tree's surface in its pose.
SeamNumbers measure(const PieceSet& set, const Tree& tree,
                    const std::vector<std::vector<std::uint16_t>>& tiles) {
  const texture::TileAtlas& atlas = texture::bundled_bark_atlas();
  const double texel = 1.0 / (atlas.cell * (1 - 2 * atlas.inset));  // one pixel, tile units
  const std::vector<Mat4> world = bone_world(tree, tree.pose);
  std::map<std::pair<std::array<long, 3>, std::array<long, 3>>, std::vector<SideRef>> edges;
  std::vector<SkinnedPiece> skinned;
  for (std::uint32_t i = 0; i < tree.pieces.size(); ++i) {
    skinned.push_back(skin_piece(set, tree, world, i, 0));
    const PieceMesh& m = set.types[tree.pieces[i].type].lods[0];
    for (std::uint32_t q = 0; q < m.quads.size(); ++q) {
      for (int k = 0; k < 4; ++k) {
        auto key = [&](std::uint32_t v) {
          const Vec3 p = skinned[i].positions[v];
          return std::array<long, 3>{std::lround(p.x * 1e4), std::lround(p.y * 1e4),
                                     std::lround(p.z * 1e4)};
        };
        auto a = key(m.quads[q][k]), b = key(m.quads[q][(k + 1) % 4]);
        const bool forward = a < b;
        edges[forward ? std::make_pair(a, b) : std::make_pair(b, a)].push_back({i, q, k, forward});
      }
    }
  }
  // Tile coordinates of the point `param` along side `s` of a quad, `depth` pixels inside.
  auto at = [&](const SideRef& r, double param, double depth) {
    const PieceMesh& m = set.types[tree.pieces[r.piece].type].lods[0];
    const auto c0 = tile_coords(m, r.quad, r.side), c1 = tile_coords(m, r.quad, (r.side + 1) % 4);
    const double p = r.forward ? param : 1 - param;
    double s = c0[0] + (c1[0] - c0[0]) * p, t = c0[1] + (c1[1] - c0[1]) * p;
    // Inwards: south (t = 1) up, east (s = 1) left, north (t = 0) down, west (s = 0) right.
    const double in[4][2] = {{0, -1}, {-1, 0}, {0, 1}, {1, 0}};
    s += in[r.side][0] * depth * texel;
    t += in[r.side][1] * depth * texel;
    const auto uv = atlas.uv(tiles[r.piece][r.quad], s, t);
    return sample(atlas.image, uv[0], uv[1]);
  };
  SeamNumbers n;
  for (const auto& [edge, sides] : edges) {
    if (sides.size() != 2) continue;
    const SideRef &x = sides[0], &y = sides[1];
    const bool regular = y.side == (x.side + 2) % 4 && x.forward != y.forward;
    double seam = 0;
    for (int j = 0; j < 32; ++j) {
      const double param = (j + 0.5) / 32;
      seam += difference(at(x, param, 0.5), at(y, param, 0.5)) / 32;
      if (regular) {
        n.inside += difference(at(x, param, 0.5), at(x, param, 1.5)) / 64;
        n.inside += difference(at(y, param, 0.5), at(y, param, 1.5)) / 64;
      }
    }
    if (regular) {
      n.seam += seam;
      ++n.regular_joins;
    } else {
      // Only the ridges of multi-branch pieces, where two branches' first quads meet south
      // edge to south edge.
      n.ridges += x.piece == y.piece && x.side == 0 && y.side == 0 &&
                  set.types[tree.pieces[x.piece].type].leaves.size() >= 2;
      n.irregular += seam;
      ++n.irregular_joins;
    }
  }
  n.seam /= std::max<std::size_t>(n.regular_joins, 1);
  n.inside /= std::max<std::size_t>(n.regular_joins, 1);
  n.irregular /= std::max<std::size_t>(n.irregular_joins, 1);
  return n;
}

}  // namespace

TEST_CASE("neighbouring quads show bark tiles that join without a seam", "[pieces][tiles]") {
  const PieceSet set = lower_text(kAlmond);
  AssembleOptions ao;
  ao.seed = 5;
  const Tree rest = assemble(set, ao);
  // In the rest pose and in a random one (tiles depend on topology, not on the pose).
  for (const Tree& tree : {rest, pose_copies(set, rest, 2, 9, 0.0).trees[1]}) {
    const BarkTiling tiling = bark_tiling(set, tree, texture::bundled_bark_atlas().edges, 3);
    REQUIRE(tiling.tiles.size() == tree.pieces.size());
    const SeamNumbers matched = measure(set, tree, tiling.tiles);
    // The same tree with its tiles drawn at random.
    std::vector<std::vector<std::uint16_t>> random = tiling.tiles;
    Rng rng = Rng::stream(7, 1);
    for (auto& piece : random)
      for (auto& t : piece) t = std::uint16_t(rng.below(16));
    const SeamNumbers shuffled = measure(set, tree, random);
    INFO("regular joins " << matched.regular_joins << ", irregular " << matched.irregular_joins
                          << "; seam " << matched.seam << " inside " << matched.inside
                          << " irregular " << matched.irregular << "; random tiles: seam "
                          << shuffled.seam);
    // Only the ridges inside forks and trifurcations are left untied; joints are regular.
    std::size_t ridges = 0;
    for (const PlacedPiece& p : tree.pieces) ridges += irregular_joins(set.types[p.type].lods[0]);
    CHECK(matched.irregular_joins == ridges);
    // The ridges of forks and trifurcations are the only irregular joins.
    CHECK(matched.ridges == matched.irregular_joins);
    CHECK(matched.irregular_joins < matched.regular_joins / 20);
    CHECK(matched.seam <= matched.inside);
    CHECK(shuffled.seam > 2 * matched.seam);
  }
}

TEST_CASE("bark tiles are seeded, and instances of a piece type draw from its variants",
          "[pieces][tiles]") {
  const PieceSet set = lower_text(kAlmond);
  AssembleOptions ao;
  ao.seed = 5;
  const Tree tree = assemble(set, ao);
  const BarkTiling a = bark_tiling(set, tree, 2, 3);
  CHECK(a.tiles == bark_tiling(set, tree, 2, 3).tiles);
  CHECK(a.tiles != bark_tiling(set, tree, 2, 4).tiles);
  // Instances of a type draw from its 8 variants, which differ.
  std::map<std::uint32_t, std::set<std::uint32_t>> used;
  std::map<std::uint32_t, std::set<std::vector<std::uint16_t>>> distinct;
  for (std::size_t i = 0; i < tree.pieces.size(); ++i) {
    CHECK(a.variant[i] < 8);
    used[tree.pieces[i].type].insert(a.variant[i]);
    distinct[tree.pieces[i].type].insert(a.tiles[i]);
  }
  for (const auto& [type, variants] : used) {
    INFO(set.types[type].name);
    CHECK(distinct[type].size() == variants.size());
  }
  CHECK(used.at(set.find("I")).size() >= 5);
  // One colour per direction: every quad shows tile 0.
  for (const auto& piece : bark_tiling(set, tree, 1, 3).tiles)
    for (std::uint16_t t : piece) CHECK(t == 0);
}

TEST_CASE("tile coordinates of tessellated quads cover their base quad's tile", "[pieces][tiles]") {
  const PieceSet set = lower_text(kAlmond);
  const PieceMesh& m = set.types[0].lods[2];
  const int n = m.segments;
  REQUIRE(n > 1);
  // The first base quad's sub-quads: corner 0 of sub-quad (i, j) at (i/n, 1 - j/n).
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const auto c0 = tile_coords(m, std::size_t(j * n + i), 0);
      const auto c2 = tile_coords(m, std::size_t(j * n + i), 2);
      CHECK(c0[0] == Approx(double(i) / n));
      CHECK(c0[1] == Approx(1 - double(j) / n));
      CHECK(c2[0] == Approx(double(i + 1) / n));
      CHECK(c2[1] == Approx(1 - double(j + 1) / n));
    }
  }
}

TEST_CASE("foliage clouds sit at the open leaf rims, leaf cards inside them", "[pieces][foliage]") {
  const PieceSet set = lower_text(kAlmond);
  AssembleOptions ao;
  ao.seed = 5;
  const Tree tree = assemble(set, ao);
  std::vector<Trs> world(tree.bones.size());
  for (std::size_t i = 0; i < tree.bones.size(); ++i) {
    const std::uint32_t p = tree.bones[i].parent;
    world[i] = p == kNone ? tree.pose[i] : world[p] * tree.pose[i];
  }
  const std::vector<FoliageCloud> clouds = foliage_clouds(set, tree, world);
  // Open rims: every leaf rim minus the pieces hanging from one.
  std::size_t rims = 0;
  for (const PlacedPiece& p : tree.pieces) rims += set.types[p.type].leaves.size();
  REQUIRE(clouds.size() == rims - (tree.pieces.size() - 1));
  for (const FoliageCloud& c : clouds) {
    const Trs& rim = world[c.bone];
    CHECK(tree.bones[c.bone].piece == c.piece);
    CHECK(c.radius > rim.s);
    // Just beyond the rim, along its axis.
    CHECK(distance(c.centre, rim.t) == Approx(0.5 * c.radius));
    CHECK(dot(c.centre - rim.t, rim.r.rotate({0, 0, 1})) > 0);
  }
  // A budget of 20 cards per cloud on average: every cloud gets 8..90, in proportion to its area.
  const int budget = int(20 * clouds.size());
  const std::vector<int> counts = cards_per_cloud(clouds, budget);
  int total = 0;
  for (std::size_t k = 0; k < clouds.size(); ++k) {
    CHECK(counts[k] >= 8);
    CHECK(counts[k] <= 90);
    total += counts[k];
    for (std::size_t j = 0; j < clouds.size(); ++j)
      if (clouds[j].radius > clouds[k].radius) CHECK(counts[j] >= counts[k]);
  }
  CHECK(std::abs(total - budget) <= int(clouds.size()));
  const LeafCards cards = leaf_cards(clouds, 11, budget);
  REQUIRE(cards.positions.size() == std::size_t(total) * 4);
  CHECK(cards.indices.size() == std::size_t(total) * 6);
  std::size_t v = 0;
  for (std::size_t k = 0; k < clouds.size(); ++k) {
    for (int n = 0; n < 4 * counts[k]; ++n, ++v) {
      CHECK(cards.bones[v] == clouds[k].bone);
      CHECK(distance(cards.positions[v], clouds[k].centre) < 1.4 * clouds[k].radius);
    }
  }
  CHECK(leaf_cards(clouds, 11, budget).positions == cards.positions);
}
