// Skins every placed piece of a forest into one TreeMesh (output_posed_mesh.h).
#include "backends/pieces/output_posed_mesh.h"

#include <string>

namespace ramus::pieces {

mesh::TreeMesh posed_forest_mesh(const PieceSet& set, const Forest& forest, std::size_t lod) {
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
  return out;
}

}  // namespace ramus::pieces
