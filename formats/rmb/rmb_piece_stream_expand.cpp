// Expands a placed-pieces stream into the instance buffer (rmb_piece_stream_expand.h). The bone
// order, the composition world = parent world x local and the skinning matrix world x inverse
// bind are those of the pieces back end's layout (backends/pieces/output_layout.cpp), with the
// same core/similarity.h operations in the same order.
#include "formats/rmb/rmb_piece_stream_expand.h"

#include <algorithm>

#include "core/rng.h"

namespace ramus {

std::vector<std::uint16_t> draw_piece_tiles(std::size_t quads,
                                            std::span<const std::uint8_t> tile_type,
                                            std::array<std::uint16_t, 2> tiles_per_type,
                                            std::uint64_t seed, std::uint32_t placed) {
  std::vector<std::uint16_t> tiles(quads);
  Rng rng = Rng::stream(seed, placed, 0x74696c65);  // "tile"
  const std::uint16_t n1 = std::max<std::uint16_t>(tiles_per_type[0], 1);
  const std::uint16_t n2 = std::max<std::uint16_t>(tiles_per_type[1], 1);
  for (std::size_t q = 0; q < quads; ++q) {
    const bool fork = q < tile_type.size() && tile_type[q] == 2;
    tiles[q] = fork ? std::uint16_t(n1 + rng.below(n2)) : std::uint16_t(rng.below(n1));
  }
  return tiles;
}

InstanceBufferTables expand_piece_stream(const RmbPieceStream& s) {
  // The sizes first, so that a stream of few bytes naming many large pieces is refused before
  // anything is allocated for it.
  std::uint64_t bones = 0, tiles = 0, instances = 0;
  for (const RmbPlacedTree& tree : s.trees) {
    for (const RmbPlacedPiece& p : tree.pieces) {
      bones += rmb_joint_count(s.types.at(p.type));
      tiles += s.types[p.type].quad_tile_type.size();
    }
    instances += tree.pieces.size();
  }
  const std::uint64_t total = instance_buffer_bytes(s.types.size(), bones, instances, tiles);
  if (bones >= 0xffffffffull || total > 0xffffffffull) {
    throw rmb::RmbError(0, "the placed pieces expand to " + std::to_string(total) +
                               " bytes, beyond the instance buffer's 32-bit offsets");
  }
  // Per type, the inverse bind matrix of each joint: identity at the root rim, the inverse of
  // the building transform at each leaf rim (backends/pieces/piece_finish.cpp).
  std::vector<std::vector<Mat4>> inverse_bind(s.types.size());
  for (std::size_t t = 0; t < s.types.size(); ++t) {
    inverse_bind[t].push_back(Mat4{});
    for (const Trs& b : s.types[t].leaves) inverse_bind[t].push_back(b.inverse().matrix());
  }
  InstanceBufferTables out;
  out.trees = std::uint32_t(s.trees.size());
  out.skinning.reserve(std::size_t(bones));
  out.tiles.reserve(std::size_t(tiles));
  std::vector<InstanceRecord> records;
  std::vector<std::uint32_t> record_type;
  std::uint32_t base = 0;
  std::vector<Trs> world;
  std::vector<std::uint32_t> piece_bone;
  for (std::size_t k = 0; k < s.trees.size(); ++k) {
    const RmbPlacedTree& tree = s.trees[k];
    world.clear();
    piece_bone.assign(tree.pieces.size(), 0);
    for (std::size_t i = 0; i < tree.pieces.size(); ++i) {
      const RmbPlacedPiece& p = tree.pieces[i];
      const RmbStreamType& type = s.types[p.type];
      const std::uint32_t offset = std::uint32_t(world.size());
      piece_bone[i] = offset;
      for (std::size_t j = 0; j < rmb_joint_count(type); ++j) {
        const Trs local = rmb_joint_local(s, tree, i, j);
        // The root joint hangs from the parent's terminal joint of its leaf rim; the others
        // from the piece's root joint.
        // (A root piece has no parent to index: piece_bone[kRmbNoParent] would read past the end.)
        if (j == 0 && p.parent == kRmbNoParent) {
          world.push_back(local);
        } else {
          const std::size_t parent = j > 0 ? offset : piece_bone[p.parent] + 1 + p.leaf;
          world.push_back(world[parent] * local);
        }
        out.skinning.push_back(world.back().matrix() * inverse_bind[p.type][j]);
      }
      InstanceRecord r;
      r.bone_offset = base + offset;
      r.tile_offset = std::uint32_t(out.tiles.size());
      r.tree = std::uint32_t(k);
      r.type = std::uint16_t(p.type);
      r.joints = std::uint16_t(rmb_joint_count(type));
      const std::vector<std::uint16_t> t =
          draw_piece_tiles(type.quad_tile_type.size(), type.quad_tile_type, s.tiles_per_type,
                           tree.tile_seed, std::uint32_t(i));
      out.tiles.insert(out.tiles.end(), t.begin(), t.end());
      records.push_back(r);
      record_type.push_back(p.type);
    }
    base += std::uint32_t(world.size());
  }
  InstanceTypeOrder order = order_instances_by_type(record_type, s.types.size());
  out.ranges = std::move(order.ranges);
  out.instances.reserve(records.size());
  for (std::uint32_t i : order.by_type) out.instances.push_back(records[i]);
  return out;
}

std::string expand_piece_stream_binary(const RmbPieceStream& stream) {
  return write_instance_buffer_binary(expand_piece_stream(stream));
}

}  // namespace ramus
