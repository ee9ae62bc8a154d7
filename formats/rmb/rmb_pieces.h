// The piece-set section of an .rmb (section 10, docs/binary-format.md): the `pieces` blocks of
// the root file (docs/pieces.md) at the level of the language -- rim, piece declarations with
// their kinds and arguments, attach rules with weights, the settings root, twist and depth --
// with every number folded, and the files of mesh("...") pieces embedded byte for byte so that
// the .rmb is self-contained.
//
// This is the section's data model and its byte codec only; it needs nothing but the standard
// library and formats/rmb/, so the embeddable runtime verifies the section like every other.
// The mapping from and to `pieces` blocks is formats/rmb/rmb_pieces_ast.h (grammar front end).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "formats/rmb/rmb_io.h"

namespace ramus {

// The piece kinds of docs/pieces.md. A mesh piece is either embedded (the file's bytes are in
// the section) or, when asked, a path as written in the source.
enum class RmbPieceKind : std::uint8_t {
  Tube = 0,
  Fork = 1,
  Trifurcation = 2,
  Attachment = 3,
  Mesh = 4,      // mesh("file"), the file embedded (RmbPieces::meshes)
  MeshPath = 5,  // mesh("file"), the path kept
};
inline constexpr int kRmbPieceKinds = 6;

// What the section needs to know of a built-in kind: its language name, its arguments in
// positional order and its leaf rims in order (docs/pieces.md, Built-in kinds).
struct RmbPieceKindInfo {
  std::string_view name;
  std::vector<std::string_view> args;
  std::vector<std::string_view> rims;
};
const RmbPieceKindInfo& rmb_piece_kind(RmbPieceKind kind);
// The kind of a language name, "mesh" for both mesh kinds; nullopt for an unknown name.
std::optional<RmbPieceKind> rmb_piece_kind_named(std::string_view name);

// One embedded mesh file: its name (a plain file name ending in .obj, .gltf or .glb, written
// next to the decompiled grammar) and its bytes.
struct RmbMeshFile {
  std::string name;
  std::string bytes;
  bool operator==(const RmbMeshFile&) const = default;
};

struct RmbPiece {
  std::string name;
  RmbPieceKind kind = RmbPieceKind::Tube;
  // Built-in kinds: each argument in the kind's positional order, set when written (the last
  // value written wins, as when the block is lowered); unset means the kind's default.
  std::vector<std::optional<double>> args;
  std::uint32_t mesh = 0;  // Mesh: index into RmbPieces::meshes
  std::string path;        // MeshPath: the file name as written
  bool operator==(const RmbPiece&) const = default;
};

struct RmbAttachTarget {
  std::uint32_t piece = 0;       // index into the block's pieces
  std::optional<double> weight;  // unset: written without a weight (1)
  bool operator==(const RmbAttachTarget&) const = default;
};

struct RmbAttachRule {  // piece.rim -> targets
  std::uint32_t piece = 0;
  std::string rim;  // a leaf rim of the piece's kind (for a mesh piece, any rim name)
  std::vector<RmbAttachTarget> targets;
  bool operator==(const RmbAttachRule&) const = default;
};

// `twist` as written: not written, one of the six twists, or `any`.
inline constexpr std::uint8_t kRmbTwistAny = 6;

struct RmbPieceSet {
  std::string name;
  bool rim = false;                    // `rim hexagon(...)` written
  std::optional<double> rim_radius;    // its radius, when given
  std::vector<RmbPiece> pieces;        // in declaration order
  std::uint32_t root = 0;              // index into pieces
  std::optional<std::uint8_t> twist;   // 0..5, or kRmbTwistAny
  std::optional<std::uint32_t> depth;  // 0..kRmbMaxPieceDepth
  std::vector<RmbAttachRule> rules;    // in block order
  bool operator==(const RmbPieceSet&) const = default;
};

// The whole section: the mesh files once each, then the blocks in file order.
struct RmbPieces {
  std::vector<RmbMeshFile> meshes;
  std::vector<RmbPieceSet> sets;
  bool empty() const { return sets.empty(); }
  bool operator==(const RmbPieces&) const = default;
};

inline constexpr std::uint32_t kRmbMaxPieceDepth = 4096;  // as the pieces backend allows
inline constexpr std::size_t kRmbMaxPiecesPerSet = 4096;
inline constexpr std::size_t kRmbMaxMeshBytes = std::size_t(16) << 20;

// A mesh file name the section accepts: 1..255 bytes of letters, digits, '.', '_' and '-', not
// starting with '.', ending (in any case) in .obj, .gltf or .glb. Being a plain name, it cannot
// point outside the folder the decompiled grammar is written to.
bool rmb_mesh_name_ok(std::string_view name);

// Writes the section. Throws RmbError (offset 0) for what the section cannot carry. Stripping
// (flag bit 2) does not change it: its names are the grammar's, not debug information.
void write_rmb_pieces(rmb::Writer& w, const RmbPieces& pieces);
// Reads and verifies the section (counts, indices, names, kinds, limits).
RmbPieces read_rmb_pieces(rmb::Reader& r);

}  // namespace ramus
