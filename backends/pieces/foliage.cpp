#include "backends/pieces/foliage.h"

#include <algorithm>
#include <cmath>

#include "mesh/frames.h"
#include "core/rng.h"

namespace ramus::pieces {
namespace {

Vec3 random_unit(Rng& rng) {
  for (;;) {
    const Vec3 v{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    const double l = length(v);
    if (l > 1e-3 && l <= 1) return v / l;
  }
}

}  // namespace

std::vector<FoliageCloud> foliage_clouds(const PieceSet& set, const Tree& tree,
                                         std::span<const Trs> world) {
  std::vector<std::vector<char>> taken(tree.pieces.size());
  for (std::size_t i = 0; i < tree.pieces.size(); ++i)
    taken[i].assign(set.types[tree.pieces[i].type].leaves.size(), 0);
  for (const PlacedPiece& p : tree.pieces)
    if (p.parent != kNone) taken[p.parent][p.parent_leaf] = 1;
  std::vector<FoliageCloud> out;
  for (std::uint32_t i = 0; i < tree.pieces.size(); ++i) {
    const PlacedPiece& p = tree.pieces[i];
    const PieceType& type = set.types[p.type];
    const Vec3 base = world[p.bone_offset + type.root.joint].t;
    for (std::size_t l = 0; l < type.leaves.size(); ++l) {
      if (taken[i][l]) continue;
      FoliageCloud c;
      c.piece = i;
      c.bone = p.bone_offset + type.leaves[l].joint;
      const Trs& rim = world[c.bone];
      const Vec3 axis = rim.r.rotate({0, 0, 1});
      // A twig's crown: about as wide as its piece is long, at least a few rims wide.
      const double piece_length = distance(rim.t, base);
      c.radius = std::max(0.8 * piece_length, 5 * rim.s);
      c.centre = rim.t + axis * (0.5 * c.radius);
      out.push_back(c);
    }
  }
  return out;
}

std::vector<FoliageCloud> forest_clouds(const PieceSet& set, const Forest& forest,
                                        const PiecesLayout& layout) {
  std::vector<FoliageCloud> all;
  for (std::size_t k = 0; k < forest.trees.size(); ++k) {
    const std::uint32_t base = layout.tree_bone_base[k];
    const std::span<const Trs> world(layout.bone_world.data() + base, forest.trees[k].bones.size());
    for (FoliageCloud c : foliage_clouds(set, forest.trees[k], world)) {
      c.bone += base;
      all.push_back(c);
    }
  }
  return all;
}

std::vector<int> cards_per_cloud(std::span<const FoliageCloud> clouds, int budget) {
  double area = 0;
  for (const FoliageCloud& c : clouds) area += c.radius * c.radius;
  std::vector<int> out;
  for (const FoliageCloud& c : clouds) {
    const double share = area > 0 ? budget * c.radius * c.radius / area : 0;
    out.push_back(std::clamp(int(std::lround(share)), 8, 90));
  }
  return out;
}

LeafCards leaf_cards(std::span<const FoliageCloud> clouds, std::uint64_t seed, int budget) {
  LeafCards out;
  const std::vector<int> counts = cards_per_cloud(clouds, budget);
  for (std::size_t k = 0; k < clouds.size(); ++k) {
    const FoliageCloud& c = clouds[k];
    const int per_cloud = counts[k];
    Rng rng = Rng::stream(seed, 0x6c656166, k);  // "leaf"
    const double len = std::min(0.26 * std::sqrt(90.0 / per_cloud), 0.6) * c.radius;
    const double width = 0.5 * len;  // the leaf texture is 1 : 2
    for (int n = 0; n < per_cloud; ++n) {
      // Denser towards the surface of the cloud, where leaves catch the light.
      const Vec3 dir = random_unit(rng);
      const double r = c.radius * std::cbrt(rng.uniform(0.15, 1.0)) * 0.9;
      const Vec3 at = c.centre + dir * r;
      // Leaves point outwards, loosely; the blade faces away from the cloud's centre.
      const Vec3 h = normalized(dir + random_unit(rng) * 0.8, dir);
      Vec3 across = cross(h, random_unit(rng));
      across = length(across) > 1e-6 ? normalized(across) : mesh::any_perpendicular(h);
      Vec3 normal = normalized(cross(h, across));
      if (dot(normal, dir) < 0) {
        across = -across;
        normal = -normal;
      }
      const Vec3 origin = at - h * (0.5 * len);
      const std::uint32_t b = std::uint32_t(out.positions.size());
      for (int corner = 0; corner < 4; ++corner) {
        const double u = corner & 1, v = corner >> 1;
        out.positions.push_back(origin + across * ((u - 0.5) * width) + h * (v * len));
        out.normals.push_back(normal);
        out.uvs.push_back({float(u), float(v)});
        out.bones.push_back(c.bone);
      }
      // Corners 0 (u0,v0) 1 (u1,v0) 2 (u0,v1) 3 (u1,v1): (0,2,3) winds about h x across.
      out.indices.insert(out.indices.end(), {b, b + 2, b + 3, b, b + 3, b + 1});
    }
  }
  return out;
}

}  // namespace ramus::pieces
