#include "compiler/grow.h"

#include "compiler/derive.h"
#include "compiler/turtle.h"

namespace ramus {

Skeleton grow_grammar(const ir::Grammar& g, const GrowOptions& options) {
  DeriveOptions d;
  d.steps = options.steps;
  d.max_modules = options.max_modules;
  d.max_bytes = options.max_bytes;
  TurtleOptions t;
  t.seed = g.settings.seed;
  t.steps = options.steps.value_or(g.settings.derive);
  t.max_modules = options.max_modules;
  t.max_bytes = options.max_bytes;
  try {
    ModuleString s = derive(g, d);
    return interpret(g, s, t);
  } catch (const DeriveError& e) {
    throw GrowError(e.what());
  }
}

Skeleton grow_file(const std::string& path, const GrowOptions& options, SourceManager& sources,
                   DiagnosticSink& diagnostics) {
  return grow_grammar(lower_file(path, options, sources, diagnostics), options);
}

Skeleton grow_checked(const Program& program, const GrowOptions& options, SourceManager& sources,
                      DiagnosticSink& diagnostics) {
  return grow_grammar(lower_checked(program, options, sources, diagnostics), options);
}

Skeleton grow_text(const std::string& name, const std::string& text, const GrowOptions& options,
                   SourceManager& sources, DiagnosticSink& diagnostics) {
  return grow_grammar(lower_text(name, text, options, sources, diagnostics), options);
}

}  // namespace ramus
