// Round-trip fuzz target for the .rmb format (docs/binary-format.md): grammar text that lowers
// cleanly is encoded (exact, quantized, zstd), decoded and encoded again, which must give the
// same bytes; and it is decompiled (formats/rmb/rmb_decompile.h), which must give text that
// parses, checks and lowers to bytecode identical code by code, and that decompiles to itself.
// Text that does not lower, and grammars the language cannot spell (DecompileError), are
// skipped; any other difference aborts.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "compiler/pipeline.h"
#include "formats/rmb/rmb_codec.h"
#include "formats/rmb/rmb_decompile.h"

namespace {

using namespace ramus;

bool lower_quietly(const std::string& text, ir::Grammar& out) {
  SourceManager sm;
  DiagnosticSink diags;
  try {
    out = lower_text("fuzz.ramus", text, GrowOptions{}, sm, diags);
    return true;
  } catch (const std::exception&) {  // GrowError, LowerError: not a grammar
    return false;
  }
}

void check_bytes(const ir::Grammar& g, const RmbEncodeOptions& o) {
  const std::string bytes = encode_rmb(g, o);
  if (encode_rmb(decode_rmb(bytes), o) != bytes) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 20'000) return 0;
  ir::Grammar g;
  if (!lower_quietly(std::string(reinterpret_cast<const char*>(data), size), g)) return 0;
  try {
    RmbEncodeOptions exact, lossy, packed;
    lossy.tolerance = 1e-3;
    packed.zstd = true;
    check_bytes(g, exact);
    check_bytes(g, lossy);
    check_bytes(g, packed);
  } catch (const RmbError&) {
    return 0;  // a grammar beyond the format's limits (encode refuses it up front)
  }
  std::string text;
  try {
    text = decompile(decode_rmb(encode_rmb(g)));
  } catch (const DecompileError&) {
    return 0;
  }
  ir::Grammar again;
  if (!lower_quietly(text, again)) std::abort();
  if (again.codes.size() != g.codes.size()) std::abort();
  for (std::size_t c = 0; c < g.codes.size(); ++c) {
    if (ir::dump_code(again, ir::CodeId(c)) != ir::dump_code(g, ir::CodeId(c))) std::abort();
  }
  if (decompile(again) != text) std::abort();
  return 0;
}
