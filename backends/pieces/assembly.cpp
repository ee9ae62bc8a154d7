// Assembling a tree from attach rules (Burkus et al. 2017, section 4.2) and laying out its bones
// in one buffer (section 4.3).
//
// Topological transform: the root piece's is the tree's placement; a piece hanging from leaf rim
// r of parent P has T = T_P * B_r * Rz(60 deg * twist), where B_r is r's building transform and
// the twist picks one of the six similarities that map the hexagonal root rim onto the leaf rim.
#include <algorithm>
#include <cmath>
#include <deque>

#include "backends/pieces/piece_build.h"
#include "core/rng.h"

namespace ramus::pieces {

Trs twist_rotation(int twist) {
  return Trs{{0, 0, 0}, Quat::axis_angle({0, 0, 1}, M_PI / 3 * twist), 1.0};
}

// Appends a placed piece and its bones; returns its index.
std::uint32_t place_piece(const PieceSet& set, Tree& tree, std::uint32_t type, std::uint32_t parent,
                          std::uint32_t leaf, int twist, const Trs& placement,
                          const TileOptions& tiles, std::uint64_t seed) {
  const PieceType& t = set.types[type];
  PlacedPiece p;
  p.type = type;
  p.parent = parent;
  p.parent_leaf = leaf;
  p.twist = std::uint8_t(twist);
  p.bone_offset = std::uint32_t(tree.bones.size());
  Bone root;
  root.piece = std::uint32_t(tree.pieces.size());
  root.joint = 0;
  if (parent == kNone) {
    p.depth = 0;
    p.topological = placement.matrix();
    root.rest = placement;
  } else {
    const PlacedPiece& pp = tree.pieces[parent];
    const PieceType& pt = set.types[pp.type];
    p.depth = pp.depth + 1;
    // The child's root joint is attached rigidly to the parent's terminal joint of that rim
    // (section 4.3): its local transform is only the twist.
    root.parent = pp.bone_offset + pt.leaves[leaf].joint;
    root.rest = twist_rotation(twist);
    p.topological = pp.topological * pt.leaves[leaf].building.matrix() * root.rest.matrix();
  }
  tree.bones.push_back(root);
  for (std::size_t j = 1; j < t.joints.size(); ++j) {
    Bone b;
    b.parent = p.bone_offset + t.joints[j].parent;
    b.piece = root.piece;
    b.joint = std::uint16_t(j);
    b.rest = t.joints[j].bind_local;
    tree.bones.push_back(b);
  }
  p.tiles = assign_tiles(t.lods[0], tiles, seed, root.piece);
  tree.pieces.push_back(std::move(p));
  return root.piece;
}

Tree assemble(const PieceSet& set, const AssembleOptions& options) {
  Tree tree;
  if (set.types.empty()) return tree;
  Trs placement = options.placement;
  placement.s *= set.rim_radius;
  place_piece(set, tree, set.root, kNone, 0, 0, placement, options.tiles, options.seed);
  // Breadth first, so a piece limit cuts the tree evenly rather than one branch deep.
  std::deque<std::uint32_t> queue{0};
  bool full = false;
  while (!queue.empty() && !full) {
    std::uint32_t pi = queue.front();
    queue.pop_front();
    const std::uint32_t type = tree.pieces[pi].type;
    const std::uint32_t depth = tree.pieces[pi].depth;
    if (int(depth) >= set.depth) continue;  // depth D: no piece deeper than D
    for (std::uint32_t leaf = 0; leaf < set.types[type].leaves.size(); ++leaf) {
      const AttachRule* rule = set.rule(type, leaf);
      if (!rule || rule->targets.empty()) continue;
      if (tree.pieces.size() >= options.max_pieces) {
        full = true;
        break;
      }
      // One draw stream per (piece, rim): the choice at a rim does not depend on the order in
      // which other rims were visited.
      Rng rng = Rng::stream(options.seed, pi, leaf);
      double total = 0;
      for (const AttachTarget& t : rule->targets) total += t.weight;
      double x = rng.uniform01() * total;
      std::uint32_t pick = rule->targets.back().piece;
      for (const AttachTarget& t : rule->targets) {
        if (x < t.weight) {
          pick = t.piece;
          break;
        }
        x -= t.weight;
      }
      int twist = set.twist_any ? int(rng.below(6)) : set.twist;
      queue.push_back(
          place_piece(set, tree, pick, pi, leaf, twist, {}, options.tiles, options.seed));
    }
  }
  tree.pose.reserve(tree.bones.size());
  for (const Bone& b : tree.bones) tree.pose.push_back(b.rest);
  return tree;
}

const AttachRule* PieceSet::rule(std::uint32_t piece, std::uint32_t leaf) const {
  for (const AttachRule& r : rules) {
    if (r.piece == piece && r.leaf == leaf) return &r;
  }
  return nullptr;
}

std::uint32_t PieceSet::find(std::string_view piece_name) const {
  for (std::size_t i = 0; i < types.size(); ++i) {
    if (types[i].name == piece_name) return std::uint32_t(i);
  }
  return kNone;
}

}  // namespace ramus::pieces
