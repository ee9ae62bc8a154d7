// Fuzz target for the front end as `ramus fmt` and `ramus check` use it together: any bytes that
// load (parse, imports) without errors are checked, formatted, loaded and checked again. The
// properties (docs/formatting.md): the formatted text loads without errors, formatting it again
// changes nothing, and the checker reports the same diagnostic codes before and after.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "grammar/check.h"
#include "grammar/format.h"
#include "grammar/loader.h"

namespace {

using namespace ramus;

struct Checked {
  bool loads = false;
  std::string formatted;
  std::vector<int> codes;  // sorted: formatting moves diagnostics, it must not change them
};

Checked load_check_format(const std::string& text) {
  SourceManager sm;
  DiagnosticSink diags;
  LoadOptions options;
  options.stdlib_dirs = {"/nonexistent-ramus-stdlib"};  // the result must not depend on the disk
  Program program = load_program_text("fuzz.ramus", text, sm, diags, options);
  Checked out;
  if (program.files.empty() || diags.has_errors()) return out;
  out.loads = true;
  check_program(program, sm, diags);
  for (const Diagnostic& d : diags.all()) out.codes.push_back(int(d.code));
  std::sort(out.codes.begin(), out.codes.end());
  out.formatted = format_file(program.files[0], sm);
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Checked first = load_check_format(std::string(reinterpret_cast<const char*>(data), size));
  if (!first.loads) return 0;  // `ramus fmt` leaves a file with errors alone
  const Checked second = load_check_format(first.formatted);
  if (!second.loads) std::abort();                        // formatting broke the syntax
  if (second.formatted != first.formatted) std::abort();  // not idempotent
  if (second.codes != first.codes) std::abort();          // format changed what check says
  return 0;
}
