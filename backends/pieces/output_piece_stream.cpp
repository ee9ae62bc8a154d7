// Encodes a forest as a placed-pieces stream (output_piece_stream.h).
#include "backends/pieces/output_piece_stream.h"

#include <cstring>
#include <string>

#include "backends/pieces/piece_build.h"
#include "formats/rmb/rmb_piece_stream_expand.h"

namespace ramus::pieces {
namespace {

// Bit for bit (so -0 differs from 0): a joint stored as at rest must give exactly its pose.
bool same_bits(const Trs& a, const Trs& b) {
  const double x[8] = {a.t.x, a.t.y, a.t.z, a.r.w, a.r.x, a.r.y, a.r.z, a.s};
  const double y[8] = {b.t.x, b.t.y, b.t.z, b.r.w, b.r.x, b.r.y, b.r.z, b.s};
  return std::memcmp(x, y, sizeof x) == 0;
}
bool same_bits(const Mat4& a, const Mat4& b) {
  return std::memcmp(a.m.data(), b.m.data(), sizeof(double) * 16) == 0;
}

RmbStreamType stream_type(const PieceType& t) {
  const auto fail = [&](const std::string& what) {
    throw PiecesError("piece " + t.name + " cannot go into a placed-pieces stream: " + what);
  };
  if (t.joints.size() != 1 + t.leaves.size() || !same_bits(t.joints[0].inverse_bind, Mat4{}))
    fail("its joints are not one at the root rim and one per leaf rim");
  RmbStreamType out;
  out.name = t.name;
  for (std::size_t i = 0; i < t.leaves.size(); ++i) {
    const Rim& rim = t.leaves[i];
    const Joint& j = t.joints[1 + i];
    if (rim.joint != 1 + i || j.parent != 0 || !same_bits(j.bind_local, rim.building) ||
        !same_bits(j.inverse_bind, rim.building.inverse().matrix())) {
      fail("the joint of leaf rim " + rim.name + " is not bound at the rim");
    }
    out.leaves.push_back(rim.building);
  }
  if (!t.lods.empty()) {
    const PieceMesh& base = t.lods[0];
    out.quad_tile_type.assign(base.quads.size(), 1);
    for (std::size_t q = 0; q < base.quads.size() && q < base.quad_tile_type.size(); ++q)
      if (base.quad_tile_type[q] == 2) out.quad_tile_type[q] = 2;
  }
  return out;
}

RmbJointPose joint_pose(const Trs& rest, const Trs& pose) {
  RmbJointPose j;
  if (same_bits(rest, pose)) return j;
  if (same_bits(Trs{rest.t, {}, rest.s}, Trs{pose.t, {}, pose.s})) {
    j.mode = RmbJointMode::Turned;
    j.rotation = rmb_quantize_rotation(rest.r.conjugate() * pose.r);
    return j;
  }
  j.mode = RmbJointMode::Moved;
  j.rotation = rmb_quantize_rotation(pose.r);
  j.t = {float(pose.t.x), float(pose.t.y), float(pose.t.z)};
  j.s = float(pose.s);
  return j;
}

}  // namespace

RmbPieceStream encode_piece_stream(const PieceSet& set, const Forest& forest,
                                   std::span<const std::uint64_t> tile_seeds,
                                   const TileOptions& tiles) {
  if (tile_seeds.size() != forest.trees.size())
    throw PiecesError("a placed-pieces stream needs one tile seed per tree");
  if (set.types.size() > kRmbMaxStreamTypes)
    throw PiecesError("a placed-pieces stream holds at most 4096 piece types");
  RmbPieceStream s;
  s.set = set.name;
  s.tiles_per_type = tiles.tiles_per_type;
  for (int k = 0; k < kRmbTwists; ++k) s.twists[k] = twist_rotation(k).r;
  for (const PieceType& t : set.types) s.types.push_back(stream_type(t));
  for (std::size_t k = 0; k < forest.trees.size(); ++k) {
    const Tree& tree = forest.trees[k];
    const auto fail = [&](std::size_t i, const std::string& what) {
      throw PiecesError("tree " + std::to_string(k) + ", piece " + std::to_string(i) +
                        ": cannot go into a placed-pieces stream: " + what);
    };
    if (tree.pieces.empty()) throw PiecesError("tree " + std::to_string(k) + " has no pieces");
    if (tree.pose.size() != tree.bones.size())
      throw PiecesError("tree " + std::to_string(k) + ": a pose per bone is needed");
    RmbPlacedTree out;
    out.placement = tree.pose[0];
    out.tile_seed = tile_seeds[k];
    std::uint32_t bone = 0;
    for (std::size_t i = 0; i < tree.pieces.size(); ++i) {
      const PlacedPiece& p = tree.pieces[i];
      if (p.type >= set.types.size()) fail(i, "an unknown piece type");
      const PieceType& type = set.types[p.type];
      RmbPlacedPiece rp;
      rp.type = p.type;
      if (i == 0) {
        if (p.parent != kNone) fail(i, "the first piece has a parent");
      } else {
        if (p.parent >= i) fail(i, "its parent does not come before it");
        if (p.parent_leaf >= set.types[tree.pieces[p.parent].type].leaves.size() || p.twist > 5)
          fail(i, "a leaf rim or twist out of range");
        rp.parent = p.parent;
        rp.leaf = p.parent_leaf;
        rp.twist = p.twist;
      }
      if (p.bone_offset != bone || bone + type.joints.size() > tree.bones.size())
        fail(i, "its bones do not follow the previous piece's");
      out.pieces.push_back(rp);
      bool posed = false;
      std::vector<RmbJointPose> joints;
      for (std::size_t j = 0; j < type.joints.size(); ++j) {
        const Bone& b = tree.bones[bone + j];
        const std::uint32_t parent = j > 0 ? bone
                                     : i == 0
                                         ? kNone
                                         : tree.pieces[p.parent].bone_offset + 1 + p.parent_leaf;
        if (b.parent != parent || b.piece != i || b.joint != j)
          fail(i, "bone " + std::to_string(bone + j) + " is not its joint " + std::to_string(j));
        joints.push_back(joint_pose(rmb_joint_rest(s, out, i, j), tree.pose[bone + j]));
        posed = posed || joints.back().mode != RmbJointMode::Rest;
      }
      if (posed) out.pieces.back().joints = std::move(joints);
      const std::size_t quads = type.lods.empty() ? 0 : type.lods[0].quads.size();
      if (p.tiles != draw_piece_tiles(quads, s.types[p.type].quad_tile_type, s.tiles_per_type,
                                      out.tile_seed, std::uint32_t(i))) {
        fail(i, "its tiles are not the draw of tile seed " + std::to_string(out.tile_seed));
      }
      bone += std::uint32_t(type.joints.size());
    }
    if (bone != tree.bones.size()) fail(tree.pieces.size(), "bones beyond the last piece's");
    s.trees.push_back(std::move(out));
  }
  return s;
}

RmbPieceStream quantize_forest_poses(const PieceSet& set, Forest& forest,
                                     std::span<const std::uint64_t> tile_seeds,
                                     const TileOptions& tiles) {
  RmbPieceStream s = encode_piece_stream(set, forest, tile_seeds, tiles);
  for (std::size_t k = 0; k < forest.trees.size(); ++k) {
    Tree& tree = forest.trees[k];
    const RmbPlacedTree& st = s.trees[k];
    for (std::size_t i = 0; i < tree.pieces.size(); ++i) {
      const std::uint32_t offset = tree.pieces[i].bone_offset;
      for (std::size_t j = 0; j < set.types[tree.pieces[i].type].joints.size(); ++j) {
        const Trs local = rmb_joint_local(s, st, i, j);
        Bone& b = tree.bones[offset + j];
        if (same_bits(b.rest, tree.pose[offset + j])) b.rest = local;
        tree.pose[offset + j] = local;
      }
    }
  }
  return s;
}

}  // namespace ramus::pieces
