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
#include <string>
#include <string_view>
#include <vector>

#include "compiler/ir.h"
#include "formats/rmb/rmb_io.h"

namespace ramus {

using rmb::RmbError;

inline constexpr std::uint16_t kRmbVersion = 1;

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
  Pieces = 10,      // reserved: piece sets
  VoxelRules = 11,  // reserved: voxel rule tables
};

// Deterministic: the same grammar always gives the same bytes. Throws RmbError (offset 0) if the
// grammar holds something the format cannot carry (an id out of range in a malformed IR).
std::string encode_rmb(const ir::Grammar& g);

struct RmbDecodeOptions {
  // Off only for fuzzing, to reach the structural checks behind the checksum.
  bool verify_checksum = true;
};

ir::Grammar decode_rmb(std::string_view bytes, const RmbDecodeOptions& options = {},
                       std::vector<rmb::TraceEntry>* trace = nullptr);

// The annotated listing of `ramus dump`: one line per field, "offset  bytes  field  value".
std::string format_rmb_trace(std::string_view bytes, const std::vector<rmb::TraceEntry>& trace);

}  // namespace ramus
