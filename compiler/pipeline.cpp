#include "compiler/pipeline.h"

#include "compiler/lower.h"
#include "grammar/check.h"
#include "grammar/loader.h"

namespace ramus {

namespace {

// "file:line:col: message" of the first error, so a GrowError reads well on its own.
std::string first_error(const SourceManager& sm, const DiagnosticSink& d) {
  for (const Diagnostic& x : d.all()) {
    if (x.severity != Severity::Error) continue;
    std::string at;
    if (x.span.file < sm.size()) {
      LineCol lc = sm.line_col(x.span.file, x.span.begin);
      at = sm.name(x.span.file) + ":" + std::to_string(lc.line) + ":" + std::to_string(lc.column) +
           ": ";
    }
    std::string more = d.error_count() > 1
                           ? " (and " + std::to_string(d.error_count() - 1) + " more error(s))"
                           : "";
    return at + x.message + more;
  }
  return "errors in the grammar";
}

}  // namespace

ir::Grammar lower_checked(const Program& program, const GrowOptions& options,
                          SourceManager& sources, DiagnosticSink& diagnostics) {
  LowerOptions lower_options;
  lower_options.system = options.system;
  lower_options.defines = options.defines;
  lower_options.seed = options.seed;
  try {
    ir::Grammar g = lower(program, sources, lower_options, diagnostics);
    if (diagnostics.has_errors()) throw GrowError(first_error(sources, diagnostics));
    return g;
  } catch (const LowerError& e) {
    throw GrowError(e.what());
  }
}

namespace {

ir::Grammar check_and_lower(const Program& program, const GrowOptions& options,
                            SourceManager& sources, DiagnosticSink& diagnostics) {
  if (diagnostics.has_errors()) throw GrowError(first_error(sources, diagnostics));
  CheckOptions check_options;
  check_options.defines = options.defines;
  check_program(program, sources, diagnostics, check_options);
  if (diagnostics.has_errors()) throw GrowError(first_error(sources, diagnostics));
  return lower_checked(program, options, sources, diagnostics);
}

}  // namespace

ir::Grammar lower_file(const std::string& path, const GrowOptions& options, SourceManager& sources,
                       DiagnosticSink& diagnostics) {
  Program program = load_program(path, sources, diagnostics);
  return check_and_lower(program, options, sources, diagnostics);
}

ir::Grammar lower_text(const std::string& name, const std::string& text, const GrowOptions& options,
                       SourceManager& sources, DiagnosticSink& diagnostics) {
  Program program = load_program_text(name, text, sources, diagnostics);
  return check_and_lower(program, options, sources, diagnostics);
}

}  // namespace ramus
