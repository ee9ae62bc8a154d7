// The binary grammar format .rmb (docs/binary-format.md): ir::Grammar <-> bytes.
//
// The byte primitives (varints, CRC-32, the bounded reader) are formats/rmb/rmb_io.h; this file
// knows the sections and the IR. The decoder verifies before it trusts: every count fits the
// bytes left, every id and range points inside its array, every expression's stack use is
// proved to stay within the VM's stack, and the CRC-32 over the file matches -- so a decoded
// grammar is safe to derive, and a corrupted or truncated file is an RmbError naming the byte
// offset and what was expected there.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/ir.h"
#include "compiler/voxel_rule.h"
#include "formats/rmb/rmb_io.h"
#include "formats/rmb/rmb_piece_stream.h"
#include "formats/rmb/rmb_pieces.h"

namespace ramus {

using rmb::RmbError;

// The version written. Version 2 leaves out what the instructions imply (the constant pool's
// repeated values, the constant operands' and jumps' absolute indices, most code records);
// version 1 files are still read (docs/binary-format.md, Versions).
inline constexpr std::uint16_t kRmbVersion = 2;
inline constexpr std::uint16_t kRmbOldestVersion = 1;

// Section ids, in the order they must appear (docs/binary-format.md, Sections).
enum class RmbSection : std::uint8_t {
  Meta = 1,
  Symbols = 2,
  Constants = 3,
  Locations = 4,
  Bytecode = 5,
  Codes = 6,
  Productions = 7,
  Axiom = 8,
  Ignored = 9,
  Pieces = 10,       // optional: the piece sets of `pieces` blocks (formats/rmb/rmb_pieces.h)
  VoxelRules = 11,   // optional: the voxel rule tables of `voxels` blocks
  PieceStream = 12,  // optional: placed pieces of assembled trees (rmb_piece_stream.h)
};

// One `voxels` block (docs/language.md) as the voxel rule table section (id 11) stores it:
// the settings that were written and the rules in block order. A rule (compiler/voxel_rule.h)
// is parent class -> eight child classes, weighted by `count`; the block has no subbands, so
// `subband` is always kDiagonalSubband (the dyads proper), and `count` 0 means the rule was
// written without `x weight`.
struct RmbVoxelTable {
  std::string name;
  std::optional<std::uint32_t> levels;   // 1..64
  std::optional<std::uint32_t> classes;  // 1..256: classes are bytes
  std::optional<std::uint64_t> seed;
  std::optional<std::string> axiom;  // the axiom grid's file name, as written
  std::vector<wavelet::VoxelRule> rules;
};

// Everything an .rmb holds: the lsystem block, the piece sets and the voxel rule tables. A file
// whose source has no lsystem block (only `pieces` blocks) holds an empty grammar whose name is
// empty (rmb_has_lsystem).
struct RmbContents {
  ir::Grammar grammar;
  std::vector<RmbVoxelTable> voxels;
  RmbPieces pieces;
  RmbPieceStream placed;  // empty unless the file holds section 12
};

// Whether the grammar stands for an lsystem block: a block always has a name, so the empty
// name marks a file built from pieces blocks alone.
inline bool rmb_has_lsystem(const ir::Grammar& g) { return !g.name.empty(); }

// Header flags (u16 at offset 6).
inline constexpr std::uint16_t kRmbQuantized = 1;  // bit 0: reals quantized (lossy, on request)
inline constexpr std::uint16_t kRmbZstd = 2;       // bit 1: the sections are one zstd frame
inline constexpr std::uint16_t kRmbStripped = 4;   // bit 2: no locations, no production texts
inline constexpr std::uint16_t kRmbKnownFlags = kRmbQuantized | kRmbZstd | kRmbStripped;

struct RmbEncodeOptions {
  // Lossy only when set: every real (settings, constants, the constant pool) is stored as the
  // nearest multiple of 2^e, the largest power of two <= 2 * tolerance, so each decoded value
  // is within `tolerance` of the original (integers and multiples of 2^e stay exact).
  std::optional<double> tolerance;
  bool zstd = false;  // compress the sections with zstd (rmb_zstd.h)
  // Leave out the debug information: source locations and production texts. A decoded
  // stripped grammar names each production by its index instead ("production 3"; see
  // rmb_stripped_location), for error messages and dumps alike.
  bool strip = false;
  // The format version to write: 2 (the default), or 1 for decoders that read only version 1
  // (ramus build --rmb-version 1; the size benchmark compares both).
  int version = kRmbVersion;
};

// What a decoded stripped file has in place of the missing debug information: production i's
// location (also that of every expression it holds) is "production i" and its text "#i";
// expressions of the axiom, and those nothing refers to, are at "axiom".
std::string rmb_stripped_location(std::size_t production);
inline constexpr std::string_view kRmbStrippedAxiomLocation = "axiom";

// The quantum exponent e for a tolerance (> 0): 2^e <= 2 * tolerance, clamped to the range
// the format allows. Throws RmbError for a tolerance that is not a positive finite number.
int rmb_quantum_exponent(double tolerance);

// Deterministic: the same grammar and options always give the same bytes. Throws RmbError
// (offset 0) if the grammar holds something the format cannot carry (an id out of range in a
// malformed IR).
std::string encode_rmb(const ir::Grammar& g, const RmbEncodeOptions& options = {});
// With voxel rule tables (section 11, written only when `voxels` is not empty).
std::string encode_rmb(const ir::Grammar& g, const std::vector<RmbVoxelTable>& voxels,
                       const RmbEncodeOptions& options = {});
// With piece sets (section 10, written only when `pieces` is not empty) and voxel rule tables.
std::string encode_rmb(const ir::Grammar& g, const std::vector<RmbVoxelTable>& voxels,
                       const RmbPieces& pieces, const RmbEncodeOptions& options = {});
// With a placed-pieces stream too (section 12, written only when `placed` is not empty).
std::string encode_rmb(const ir::Grammar& g, const std::vector<RmbVoxelTable>& voxels,
                       const RmbPieces& pieces, const RmbPieceStream& placed,
                       const RmbEncodeOptions& options = {});

struct RmbDecodeOptions {
  // Off only for fuzzing, to reach the structural checks behind the checksum.
  bool verify_checksum = true;
};

ir::Grammar decode_rmb(std::string_view bytes, const RmbDecodeOptions& options = {},
                       std::vector<rmb::TraceEntry>* trace = nullptr);
// The same, with the piece sets, the voxel rule tables and the placed-pieces stream (verified
// like everything else).
RmbContents decode_rmb_contents(std::string_view bytes, const RmbDecodeOptions& options = {},
                                std::vector<rmb::TraceEntry>* trace = nullptr);

// The file as a plain (uncompressed) image: the bytes themselves, or for a zstd file (flag bit
// 1) the header with that bit cleared, the decompressed table and sections, and the CRC-32.
// Checks the header and the checksum first. Dumps list the image.
std::string rmb_uncompressed(std::string_view bytes, const RmbDecodeOptions& options = {});

// The annotated listing of `ramus dump`: one line per field, "offset  bytes  field  value".
std::string format_rmb_trace(std::string_view bytes, const std::vector<rmb::TraceEntry>& trace);

}  // namespace ramus
