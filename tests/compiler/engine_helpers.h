// Helpers for the engine tests: grammar text -> ir::Grammar -> derived string / skeleton.
#pragma once

#include <string>

#include "compiler/derive.h"
#include "compiler/grow.h"
#include "compiler/ir.h"
#include "compiler/module_string.h"
#include "compiler/pipeline.h"
#include "compiler/turtle.h"
#include "grammar/diagnostic.h"
#include "grammar/source.h"

namespace ramus::test {

inline ir::Grammar grammar_of(const std::string& text, const GrowOptions& options = {}) {
  SourceManager sm;
  DiagnosticSink diags;
  return lower_text("test.ramus", text, options, sm, diags);
}

inline ModuleString derive_of(const ir::Grammar& g, int steps, int threads = 0,
                              std::uint64_t max_modules = 100'000'000) {
  DeriveOptions d;
  d.steps = steps;
  d.threads = threads;
  d.max_modules = max_modules;
  return derive(g, d);
}

// The string after `steps` steps in ABOP notation.
inline std::string derive_text(const std::string& text, int steps) {
  ir::Grammar g = grammar_of(text);
  return to_text(g, derive_of(g, steps));
}

inline Skeleton skeleton_of(const std::string& text, int steps) {
  ir::Grammar g = grammar_of(text);
  ModuleString s = derive_of(g, steps);
  TurtleOptions t;
  t.seed = g.settings.seed;
  t.steps = steps;
  return interpret(g, s, t);
}

// The skeleton of a lowered grammar (possibly altered by the test) at its own `derive N`.
inline Skeleton skeleton_of_grammar(const ir::Grammar& g) {
  ModuleString s = derive(g, DeriveOptions{});
  TurtleOptions t;
  t.seed = g.settings.seed;
  t.steps = g.settings.derive;
  return interpret(g, s, t);
}

}  // namespace ramus::test
