// Fuzz target for the front end: any bytes as a .ramus file through load_program_text (pre-scan,
// parser, recovery), then the semantic checks and both diagnostic renderings. Nothing may crash,
// hang or read out of bounds, and every diagnostic must point inside the text.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "grammar/check.h"
#include "grammar/loader.h"
#include "grammar/parser.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  ramus::SourceManager sm;
  ramus::DiagnosticSink diags;
  // No stdlib: the input may `import` anything, and the result must not depend on the disk.
  ramus::LoadOptions options;
  options.stdlib_dirs = {"/nonexistent-ramus-stdlib"};
  ramus::Program program = ramus::load_program_text("fuzz.ramus", text, sm, diags, options);
  if (!program.files.empty()) ramus::check_program(program, sm, diags);
  for (const ramus::Diagnostic& d : diags.all()) {
    if (d.span.file >= sm.size() || d.span.begin > d.span.end ||
        d.span.end > sm.text(d.span.file).size()) {
      std::abort();  // a span outside its file would make the renderers lie
    }
  }
  diags.sort();
  std::string rendered = ramus::render_text(sm, diags.all()) + ramus::render_json(sm, diags.all());
  return rendered.empty() && !diags.all().empty() ? 1 : 0;
}
