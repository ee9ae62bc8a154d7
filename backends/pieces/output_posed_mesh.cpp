// Skins every placed piece of a forest into one TreeMesh (output_posed_mesh.h).
#include "backends/pieces/output_posed_mesh.h"

#include <string>

#include "backends/pieces/foliage.h"
#include "backends/pieces/output_layout.h"

namespace ramus::pieces {

namespace {

// The cards as two-faced leaves of the preview (it draws front faces only).
void add_leaves(const LeafCards& cards, mesh::MeshPart& leaves) {
  for (int face = 0; face < 2; ++face) {
    const std::uint32_t base = std::uint32_t(leaves.positions.size());
    for (std::size_t v = 0; v < cards.positions.size(); ++v) {
      leaves.positions.push_back(Vec3f(cards.positions[v]));
      leaves.normals.push_back(Vec3f(face == 0 ? cards.normals[v] : -cards.normals[v]));
      leaves.uvs.push_back(cards.uvs[v]);
      leaves.wind.push_back({0, 0, 0, 0});
      leaves.skin_node.push_back(kNoParent);
    }
    for (std::size_t i = 0; i < cards.indices.size(); i += 3) {
      const std::uint32_t a = cards.indices[i], b = cards.indices[i + 1], c = cards.indices[i + 2];
      if (face == 0) {
        leaves.indices.insert(leaves.indices.end(), {base + a, base + b, base + c});
      } else {
        leaves.indices.insert(leaves.indices.end(), {base + a, base + c, base + b});
      }
    }
  }
}

}  // namespace

mesh::TreeMesh posed_forest_mesh(const PieceSet& set, const Forest& forest, std::size_t lod,
                                 std::uint64_t leaf_seed) {
  mesh::TreeMesh out;
  out.name = set.name;
  mesh::MeshPart& bark = out.bark;
  for (const Tree& tree : forest.trees) {
    const std::vector<Mat4> world = bone_world(tree, tree.pose);
    for (std::uint32_t i = 0; i < tree.pieces.size(); ++i) {
      const PieceType& type = set.types.at(tree.pieces[i].type);
      if (lod >= type.lods.size()) {
        throw PiecesError("piece " + type.name + " has no level of detail " + std::to_string(lod));
      }
      const PieceMesh& m = type.lods[lod];
      const SkinnedPiece s = skin_piece(set, tree, world, i, lod);
      const std::uint32_t base = std::uint32_t(bark.positions.size());
      for (std::size_t v = 0; v < s.positions.size(); ++v) {
        bark.positions.push_back(Vec3f(s.positions[v]));
        bark.normals.push_back(Vec3f(normalized(s.normals[v])));
        bark.uvs.push_back(m.uvs[v]);
        // Wind weights are the mesh back end's; pieces sway through their bones instead.
        bark.wind.push_back({0, 0, 0, 0});
      }
      for (const auto& q : m.quads) {
        for (int k : {0, 1, 2, 0, 2, 3}) bark.indices.push_back(base + q[k]);
      }
    }
  }
  const PiecesLayout layout = layout_forest(set, forest);
  add_leaves(leaf_cards(forest_clouds(set, forest, layout), leaf_seed), out.leaves);
  return out;
}

}  // namespace ramus::pieces
