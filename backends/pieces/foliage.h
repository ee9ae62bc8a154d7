// Foliage on assembled trees (Burkus et al. 2017, section 6: "The positions of the billboards are
// determined by the pieces of the tree, which can be assigned foliage in the tree generation
// phase"). The foliage anchors are the open leaf rims, the branch tips where no piece goes on:
// each carries a leaf cloud, a sphere just beyond the rim sized by its piece, filled with leaf
// cards (the leaf outline of backends/mesh/leaf_shape.h as an alpha-tested texture). The cloud's
// centre and radius are what an engine draws a 2.5D impostor of; the cards are what a plain glTF
// viewer draws.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "backends/pieces/output_layout.h"
#include "backends/pieces/pieces.h"

namespace ramus::pieces {

struct FoliageCloud {
  std::uint32_t piece = 0;  // the placed piece whose open leaf rim anchors it
  std::uint32_t bone = 0;  // the tree's bone of that rim (its terminal joint); the cloud follows it
  Vec3 centre;             // world, z up, in the pose of `world`
  double radius = 0;
};

// The clouds of one tree, from its bones' world transforms (bone_world / PiecesLayout), in piece
// order and rim order.
std::vector<FoliageCloud> foliage_clouds(const PieceSet& set, const Tree& tree,
                                         std::span<const Trs> world);

// The clouds of every tree of a forest, tree by tree, with `bone` the global bone (PiecesLayout).
std::vector<FoliageCloud> forest_clouds(const PieceSet& set, const Forest& forest,
                                        const PiecesLayout& layout);

// How many leaf cards each cloud gets: `budget` shared in proportion to the clouds' areas
// (radius squared), at least 8 and at most 90 per cloud (a tree of many small tips gets fewer,
// larger leaves per tip; the file stays a few MB for thousands of tips).
std::vector<int> cards_per_cloud(std::span<const FoliageCloud> clouds, int budget);

// Leaf cards filling the clouds: one-faced quads (draw them double-sided), placed and turned by
// ramus::Rng from `seed`; a cloud with n cards gets leaves 0.26 x radius x sqrt(90 / n) long (at
// most 0.6 x radius), so fewer cards cover about as much. Positions and normals in the world of
// the clouds.
struct LeafCards {
  std::vector<Vec3> positions, normals;
  std::vector<std::array<float, 2>> uvs;  // leaf-card coordinates (leaf_shape.h)
  std::vector<std::uint32_t> bones;       // per vertex: its cloud's bone
  std::vector<std::uint32_t> indices;     // triangles
};
LeafCards leaf_cards(std::span<const FoliageCloud> clouds, std::uint64_t seed, int budget = 3000);

}  // namespace ramus::pieces
