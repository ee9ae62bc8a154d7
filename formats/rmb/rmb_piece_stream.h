// The placed-pieces stream of an .rmb (section 12, docs/binary-format.md): one or more trees
// assembled from a piece set, each placed piece in a few bytes -- its piece type, the parent's
// leaf rim it hangs from, its twist and, only where the tree is posed, its joints' quantized
// poses. A piece's pose is not stored as a matrix: the expansion
// (formats/rmb/rmb_piece_stream_expand.h) rebuilds every bone's local transform from the stream
// (the twist's rotation, the leaf rim's building transform, or the quantized pose) and composes
// the bones along their parents with the code of core/similarity.h, the same code the pieces back
// end composes them with (Burkus et al. 2017, sections 4.2 and 4.3).
//
// Equality. Every number the expansion starts from is stored exactly (f64 for the twists,
// buildings and placements; a quantized pose is defined by its integers) and the expansion uses
// only IEEE-754 basic operations (+ - * / sqrt) on them, so the back end that writes the
// dequantized pose into its own tree (rmb_joint_local) and the expansion compute the same bits.
//
// Data model and byte codec only: standard library, core/ and formats/rmb/rmb_io.h, so the
// embeddable runtime reads and verifies the section like every other.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/similarity.h"
#include "formats/rmb/rmb_io.h"

namespace ramus {

inline constexpr std::uint32_t kRmbNoParent = 0xffffffffu;
inline constexpr std::size_t kRmbMaxStreamTypes = 4096;
inline constexpr std::size_t kRmbMaxStreamLeaves = 255;  // leaf rims per piece type
inline constexpr std::size_t kRmbMaxStreamQuads = std::size_t(1) << 20;
inline constexpr int kRmbTwists = 6;

// What the expansion needs of a piece type. Every type has the joints the pieces back end gives
// it (backends/pieces/piece_finish.cpp): joint 0 at the root rim (identity bind pose), joint
// 1 + i at leaf rim i with the rim's building transform as its local bind pose and that
// transform's inverse as its inverse bind matrix.
struct RmbStreamType {
  std::string name;
  std::vector<Trs> leaves;                   // building transform of each leaf rim
  std::vector<std::uint8_t> quad_tile_type;  // per base quad (LOD 0): 1 (tube) or 2 (fork)
  bool operator==(const RmbStreamType&) const = default;
};

// A unit quaternion quantized by its smallest three components (the largest one is
// recomputed, and made positive by the sign of the whole quaternion): each of the three stored
// as k * 2^-16 with |k| <= kRmbRotationMaxK, in the order w, x, y, z without the largest.
inline constexpr int kRmbRotationBits = 16;
inline constexpr std::int32_t kRmbRotationMaxK = 46341;  // ceil(2^16 / sqrt 2)
struct RmbRotation {
  std::uint8_t largest = 0;  // 0 w, 1 x, 2 y, 3 z
  std::array<std::int32_t, 3> k{0, 0, 0};
  bool operator==(const RmbRotation&) const = default;
};
RmbRotation rmb_quantize_rotation(const Quat& q);
Quat rmb_rotation(const RmbRotation& r);

// A joint's pose in the stream.
enum class RmbJointMode : std::uint8_t {
  Rest = 0,    // the rest transform: placement, twist or leaf building (nothing stored)
  Turned = 1,  // the rest transform turned: rotation = rest rotation x `rotation`
  Moved = 2,   // its own similarity: `t`, `rotation`, `s` (binary32 translation and scale)
};
struct RmbJointPose {
  RmbJointMode mode = RmbJointMode::Rest;
  RmbRotation rotation;
  std::array<float, 3> t{0, 0, 0};
  float s = 1;
  bool operator==(const RmbJointPose&) const = default;
};

struct RmbPlacedPiece {
  std::uint32_t type = 0;
  std::uint32_t parent = kRmbNoParent;  // index into the tree's pieces, before this one
  std::uint32_t leaf = 0;               // the parent's leaf rim it hangs from
  std::uint8_t twist = 0;               // 0..5: 60 * twist degrees about the rim axis
  std::vector<RmbJointPose> joints;     // empty: all at rest; else one per joint of its type
  bool operator==(const RmbPlacedPiece&) const = default;
};

struct RmbPlacedTree {
  Trs placement;                       // rest local transform of the root piece's root joint
  std::uint64_t tile_seed = 0;         // the seed of its tiles (section 5.1)
  std::vector<RmbPlacedPiece> pieces;  // parents first; pieces[0] is the root piece
  bool operator==(const RmbPlacedTree&) const = default;
};

struct RmbPieceStream {
  std::string set;  // the piece set's name
  std::array<std::uint16_t, 2> tiles_per_type{4, 2};
  // The rotation of each twist about the rim axis z, as the back end computed it (x = y = 0).
  std::array<Quat, kRmbTwists> twists{};
  std::vector<RmbStreamType> types;
  std::vector<RmbPlacedTree> trees;
  bool empty() const { return trees.empty(); }
  bool operator==(const RmbPieceStream& o) const;
};

// Joints of a type: the root joint and one per leaf rim.
inline std::size_t rmb_joint_count(const RmbStreamType& t) { return 1 + t.leaves.size(); }

// The local transform of joint `joint` of piece `piece` of tree `tree`: what the expansion
// composes, and what the back end writes back into its tree so that both agree bit for bit.
Trs rmb_joint_local(const RmbPieceStream& s, const RmbPlacedTree& tree, std::size_t piece,
                    std::size_t joint);
// The rest local transform (mode Rest) of that joint.
Trs rmb_joint_rest(const RmbPieceStream& s, const RmbPlacedTree& tree, std::size_t piece,
                   std::size_t joint);

// Writes the section. Throws RmbError (offset 0) for what it cannot carry (an index out of
// range, a parent after its child, too many types).
void write_rmb_piece_stream(rmb::Writer& w, const RmbPieceStream& stream);
// Reads and verifies the section: counts, indices, parents before children, leaf rims of the
// parent's type, twists, joint modes, finite positive transforms; RmbError at the offset.
RmbPieceStream read_rmb_piece_stream(rmb::Reader& r);

// The bytes the section's tree records take (without the set's header: name, tile options,
// twists, piece types): what "bytes per piece" counts.
std::size_t rmb_piece_stream_tree_bytes(const RmbPieceStream& stream);

}  // namespace ramus
