// The numbers every output of the pieces back end shares, computed once from an assembled
// forest: one global bone buffer (every tree's bones one after the other, section 4.3: "We place
// the transformations of all bones of an animated tree in a single buffer"), each placed piece's
// global bone offset, the tile slices of all instances in one table (section 5.1: "part of the
// instance data, along with the bone index offset"), and the instances grouped by piece type so
// that one instanced draw call per type draws them all (section 3).
#pragma once

#include <cstdint>
#include <vector>

#include "backends/pieces/pieces.h"
#include "formats/pieces_instance_buffer.h"

namespace ramus::pieces {

struct OutputInstance {
  std::uint32_t tree = 0;         // index into Forest::trees
  std::uint32_t piece = 0;        // index into that tree's pieces
  std::uint32_t type = 0;         // index into PieceSet::types
  std::uint32_t bone_offset = 0;  // global: tree_bone_base[tree] + PlacedPiece::bone_offset
  std::uint32_t tile_offset = 0;  // first entry of its tiles in PiecesLayout::tiles
  std::uint32_t tile_count = 0;   // base quads of its piece type
};

// first: into PiecesLayout::by_type; count.
using TypeRange = InstanceTypeRange;

struct PiecesLayout {
  std::vector<std::uint32_t> tree_bone_base;  // global index of each tree's bone 0
  std::vector<std::uint32_t> bone_parent;     // global parent per bone, kNone for tree roots
  std::vector<std::uint32_t> bone_type;       // piece type of the piece owning each bone
  std::vector<std::uint16_t> bone_joint;      // local joint index of each bone in its piece
  std::vector<Trs> bone_local;                // Tree::pose, all trees
  std::vector<Trs> bone_world;                // composed along the parents (similarities)
  // world x inverse bind matrix of the bone's joint: a vertex bound with weight 1 to the bone
  // goes from piece space to tree space through this one matrix (what a skinning shader reads).
  std::vector<Mat4> skinning;
  std::vector<OutputInstance> instances;  // tree by tree, pieces in tree order
  std::vector<std::uint32_t> by_type;     // instance indices ordered by (type, tree, piece)
  std::vector<TypeRange> type_ranges;     // per piece type: its run in by_type
  std::vector<std::uint16_t> tiles;       // every instance's tiles, in `instances` order

  std::size_t bone_count() const { return bone_local.size(); }
};

// Checks the forest against the set (piece types, bone counts, tile counts, pose sizes) and
// lays it out. Throws PiecesError naming the first inconsistency.
PiecesLayout layout_forest(const PieceSet& set, const Forest& forest);

// The global bone buffer with other local transforms (e.g. a key of a wind clip), in the same
// order as PiecesLayout::bone_local.
std::vector<Trs> compose_world(const PiecesLayout& layout, const std::vector<Trs>& locals);

}  // namespace ramus::pieces
