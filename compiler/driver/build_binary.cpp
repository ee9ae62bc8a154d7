#include "compiler/driver/build_binary.h"

#include <cstdio>

#include "compiler/driver/defines.h"
#include "compiler/pipeline.h"
#include "compiler/rmb_codec.h"
#include "core/atomic_file.h"
#include "grammar/diagnostic.h"
#include "grammar/source.h"

namespace ramus::cli {

int build_binary(const GrowArgs& a, const std::string& output, bool quiet) {
  GrowOptions opt;
  opt.system = a.system;
  opt.seed = a.seed;
  opt.defines = parse_defines(a.defines);
  SourceManager sources;
  DiagnosticSink diags;
  ir::Grammar g;
  try {
    g = lower_file(a.file, opt, sources, diags);
  } catch (const GrowError& e) {
    diags.sort();
    std::fputs(render_text(sources, diags.all()).c_str(), stderr);
    if (!diags.has_errors()) throw UserError(e.what());
    return 1;
  }
  if (!diags.all().empty()) {
    diags.sort();
    std::fputs(render_text(sources, diags.all()).c_str(), stderr);
  }
  if (a.steps) g.settings.derive = *a.steps;
  const std::string bytes = encode_rmb(g);
  write_file_atomically(output, bytes);
  if (!quiet) {
    std::fprintf(stderr, "ramus: wrote %s (%zu bytes: %zu symbols, %zu productions)\n",
                 output.c_str(), bytes.size(), g.symbols.size(), g.productions.size());
  }
  return 0;
}

}  // namespace ramus::cli
