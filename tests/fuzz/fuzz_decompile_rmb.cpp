// Fuzz target for the .rmb decompiler (formats/rmb/rmb_decompile.h, `ramus decompile`): any bytes
// that decode (checksum checked and not, so mutations reach the structure behind it) either
// decompile or raise DecompileError; the text must then load and check without errors, and a
// file with only an lsystem block must lower again and decompile to the same text.
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "compiler/pipeline.h"
#include "formats/rmb/rmb_codec.h"
#include "formats/rmb/rmb_decompile.h"
#include "grammar/check.h"
#include "grammar/loader.h"

namespace {

using namespace ramus;

void check_text(const RmbContents& contents, const std::string& text) {
  SourceManager sm;
  DiagnosticSink diags;
  LoadOptions options;
  options.stdlib_dirs = {"/nonexistent-ramus-stdlib"};
  Program program = load_program_text("decompiled.ramus", text, sm, diags, options);
  if (program.files.empty() || diags.has_errors()) std::abort();
  check_program(program, sm, diags);
  if (diags.has_errors()) std::abort();
  if (!contents.pieces.empty() || !contents.voxels.empty()) {
    return;  // pieces and voxels name files beside the text: lowering them needs the disk
  }
  ir::Grammar again;
  try {
    SourceManager sm2;
    DiagnosticSink diags2;
    again = lower_text("decompiled.ramus", text, GrowOptions{}, sm2, diags2);
  } catch (const std::exception&) {
    std::abort();  // text that checks cleanly must lower
  }
  if (decompile(again) != text) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view bytes(reinterpret_cast<const char*>(data), size);
  for (bool checksum : {true, false}) {
    RmbDecodeOptions options;
    options.verify_checksum = checksum;
    RmbContents contents;
    std::string text;
    try {
      contents = decode_rmb_contents(bytes, options);
      text = decompile(contents);
    } catch (const RmbError&) {
      continue;
    } catch (const DecompileError&) {
      continue;
    }
    check_text(contents, text);
  }
  return 0;
}
