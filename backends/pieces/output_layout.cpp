// Lays out an assembled forest for the writers (output_layout.h).
#include "backends/pieces/output_layout.h"

#include <string>

namespace ramus::pieces {

std::vector<Trs> compose_world(const PiecesLayout& layout, const std::vector<Trs>& locals) {
  std::vector<Trs> world(locals.size());
  for (std::size_t b = 0; b < locals.size(); ++b) {
    const std::uint32_t p = layout.bone_parent[b];
    world[b] = p == kNone ? locals[b] : world[p] * locals[b];
  }
  return world;
}

PiecesLayout layout_forest(const PieceSet& set, const Forest& forest) {
  PiecesLayout out;
  out.type_ranges.resize(set.types.size());
  std::uint32_t base = 0;
  for (std::size_t k = 0; k < forest.trees.size(); ++k) {
    const Tree& tree = forest.trees[k];
    const std::string where = "tree " + std::to_string(k) + ": ";
    if (tree.pose.size() != tree.bones.size()) {
      throw PiecesError(where + "the pose has " + std::to_string(tree.pose.size()) +
                        " transforms for " + std::to_string(tree.bones.size()) + " bones");
    }
    if (std::uint64_t(base) + tree.bones.size() >= kNone) {
      throw PiecesError("the forest has more bones than 32-bit offsets can address");
    }
    out.tree_bone_base.push_back(base);
    for (std::size_t b = 0; b < tree.bones.size(); ++b) {
      const Bone& bone = tree.bones[b];
      if (bone.parent != kNone && bone.parent >= b) {
        throw PiecesError(where + "bone " + std::to_string(b) + " comes before its parent");
      }
      if (bone.piece >= tree.pieces.size()) {
        throw PiecesError(where + "bone " + std::to_string(b) + " names no placed piece");
      }
      out.bone_parent.push_back(bone.parent == kNone ? kNone : base + bone.parent);
      out.bone_type.push_back(tree.pieces[bone.piece].type);
      out.bone_joint.push_back(bone.joint);
      out.bone_local.push_back(tree.pose[b]);
    }
    for (std::size_t i = 0; i < tree.pieces.size(); ++i) {
      const PlacedPiece& p = tree.pieces[i];
      if (p.type >= set.types.size()) {
        throw PiecesError(where + "piece " + std::to_string(i) + " has an unknown type");
      }
      const PieceType& type = set.types[p.type];
      const std::size_t quads = type.lods.empty() ? 0 : type.lods[0].quads.size();
      if (std::size_t(p.bone_offset) + type.joints.size() > tree.bones.size()) {
        throw PiecesError(where + "piece " + std::to_string(i) + " (" + type.name +
                          ") has bones beyond the tree's bone buffer");
      }
      for (std::size_t j = 0; j < type.joints.size(); ++j) {
        const Bone& bone = tree.bones[p.bone_offset + j];
        if (bone.piece != i || bone.joint != j) {
          throw PiecesError(where + "the bones of piece " + std::to_string(i) +
                            " are not its joints in order");
        }
      }
      if (p.tiles.size() != quads) {
        throw PiecesError(where + "piece " + std::to_string(i) + " has " +
                          std::to_string(p.tiles.size()) + " tiles for " + std::to_string(quads) +
                          " quads");
      }
      OutputInstance inst;
      inst.tree = std::uint32_t(k);
      inst.piece = std::uint32_t(i);
      inst.type = p.type;
      inst.bone_offset = base + p.bone_offset;
      inst.tile_offset = std::uint32_t(out.tiles.size());
      inst.tile_count = std::uint32_t(quads);
      out.tiles.insert(out.tiles.end(), p.tiles.begin(), p.tiles.end());
      out.instances.push_back(inst);
    }
    base += std::uint32_t(tree.bones.size());
  }
  out.bone_world = compose_world(out, out.bone_local);
  out.skinning.resize(out.bone_world.size());
  for (std::size_t b = 0; b < out.bone_world.size(); ++b) {
    const Joint& joint = set.types[out.bone_type[b]].joints.at(out.bone_joint[b]);
    out.skinning[b] = out.bone_world[b].matrix() * joint.inverse_bind;
  }
  std::vector<std::uint32_t> instance_type;
  for (const OutputInstance& inst : out.instances) instance_type.push_back(inst.type);
  InstanceTypeOrder order = order_instances_by_type(instance_type, set.types.size());
  out.by_type = std::move(order.by_type);
  out.type_ranges = std::move(order.ranges);
  return out;
}

}  // namespace ramus::pieces
