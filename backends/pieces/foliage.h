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

// Leaf cards filling the clouds: one-faced quads (draw them double-sided), `per_cloud` each,
// placed and turned by ramus::Rng from `seed`. Positions and normals in the world of the clouds.
struct LeafCards {
  std::vector<Vec3> positions, normals;
  std::vector<std::array<float, 2>> uvs;  // leaf-card coordinates (leaf_shape.h)
  std::vector<std::uint32_t> bones;       // per vertex: its cloud's bone
  std::vector<std::uint32_t> indices;     // triangles
};
LeafCards leaf_cards(std::span<const FoliageCloud> clouds, std::uint64_t seed, int per_cloud = 90);

}  // namespace ramus::pieces
