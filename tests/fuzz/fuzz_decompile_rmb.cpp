// Fuzz target for the .rmb decompiler (formats/rmb/rmb_decompile.h, `ramus decompile`): any bytes
// that decode (checksum checked and not, so mutations reach the structure behind it) either
// decompile or raise DecompileError; the text must then load and check without errors, and a
// file with only an lsystem block must lower again, and reach a fixed point of lowering and
// decompiling after one round.
#include <cstdint>
#include <cstdio>
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

// Prints what broke, the decompiled text and its diagnostics, then aborts (the fuzzer keeps the
// input; the replay test fails with this message).
[[noreturn]] void fail(const char* why, const std::string& text, const SourceManager* sm,
                       const DiagnosticSink* diags) {
  std::fprintf(stderr, "decompile_rmb: %s\n--- decompiled text ---\n%s\n", why, text.c_str());
  if (sm && diags) std::fprintf(stderr, "%s", render_text(*sm, diags->all()).c_str());
  std::abort();
}

ir::Grammar lower_or_fail(const std::string& text) {
  try {
    SourceManager sm;
    DiagnosticSink diags;
    return lower_text("decompiled.ramus", text, GrowOptions{}, sm, diags);
  } catch (const std::exception& e) {
    fail(e.what(), text, nullptr, nullptr);  // text that checks cleanly must lower
  }
}

void check_text(const RmbContents& contents, const std::string& text) {
  SourceManager sm;
  DiagnosticSink diags;
  LoadOptions options;
  options.stdlib_dirs = {"/nonexistent-ramus-stdlib"};
  Program program = load_program_text("decompiled.ramus", text, sm, diags, options);
  if (program.files.empty() || diags.has_errors())
    fail("the text does not parse", text, &sm, &diags);
  check_program(program, sm, diags);
  if (diags.has_errors()) fail("the text does not check", text, &sm, &diags);
  if (!contents.pieces.empty() || !contents.voxels.empty()) {
    return;  // pieces and voxels name files beside the text: lowering them needs the disk
  }
  // Bytes the compiler did not write may hold code it would have folded (`param * 0.75`), so
  // the text may change once through lowering; after that it is a fixed point.
  const std::string twice = decompile(lower_or_fail(text));
  if (twice == text) return;
  const std::string thrice = decompile(lower_or_fail(twice));
  if (thrice != twice) {
    fail("the text is no fixed point of lowering and decompiling",
         twice + "\n--- and then ---\n" + thrice, nullptr, nullptr);
  }
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
