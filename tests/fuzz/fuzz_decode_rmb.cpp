// Fuzz target for the .rmb decoder (docs/binary-format.md): any input either decodes or raises
// RmbError. The checksum is tried both on and off, so mutated files reach the structural checks
// behind it. A grammar that decodes must re-encode to bytes that decode to the same bytes
// again, and must derive a few steps (under small limits) without crashing. Placed pieces
// (section 12) that decode re-encode to the same stream and expand (when small) without
// crashing.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "compiler/derive.h"
#include "compiler/expr_vm.h"
#include "formats/rmb/rmb_codec.h"
#include "formats/rmb/rmb_piece_stream_expand.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view bytes(reinterpret_cast<const char*>(data), size);
  for (bool checksum : {true, false}) {
    ramus::RmbDecodeOptions options;
    options.verify_checksum = checksum;
    try {
      const ramus::ir::Grammar g = ramus::decode_rmb(bytes, options);
      const std::string again = ramus::encode_rmb(g);
      if (ramus::encode_rmb(ramus::decode_rmb(again)) != again) std::abort();
      ramus::DeriveOptions d;
      d.steps = std::min(g.settings.derive, 4);
      d.max_modules = 20'000;
      d.threads = 1;
      try {
        ramus::derive(g, d);
      } catch (const ramus::DeriveError&) {
      } catch (const ramus::ExprError&) {
      }
    } catch (const ramus::RmbError&) {
    }
    try {
      const ramus::RmbContents c = ramus::decode_rmb_contents(bytes, options);
      if (c.placed.empty()) continue;
      const std::string again = ramus::encode_rmb(c.grammar, c.voxels, c.pieces, c.placed);
      if (!(ramus::decode_rmb_contents(again).placed == c.placed)) std::abort();
      std::size_t bones = 0;
      for (const ramus::RmbPlacedTree& t : c.placed.trees)
        for (const ramus::RmbPlacedPiece& p : t.pieces)
          bones += ramus::rmb_joint_count(c.placed.types[p.type]);
      if (bones <= 100'000) ramus::expand_piece_stream(c.placed);
    } catch (const ramus::RmbError&) {
    }
  }
  return 0;
}
