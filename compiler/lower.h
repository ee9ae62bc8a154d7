// Lowering: a checked Program (AST of the root file and its imports) -> ir::Grammar for one
// `lsystem` block. Constants and params are folded (grammar/const_eval.h, the same arithmetic as
// the checks), params may be overridden (-D), multi-letter module names are split as
// docs/language.md says (grammar/modules.h), and every expression becomes bytecode.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "compiler/ir.h"
#include "grammar/diagnostic.h"
#include "grammar/loader.h"
#include "grammar/source.h"

namespace ramus {

struct LowerOptions {
  std::string system;  // the lsystem block; empty: the first one of the root file
  std::vector<std::pair<std::string, double>> defines;  // -D name=value, params only
  std::optional<std::uint64_t> seed;                    // overrides `seed S`
};

// A problem that has no place in the source: no such lsystem, -D of a name that is not a param.
struct LowerError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Problems located in the source (which the checks should have caught) go to `diagnostics`; the
// caller must look at diagnostics.has_errors() before using the result.
ir::Grammar lower(const Program& program, const SourceManager& sources, const LowerOptions& options,
                  DiagnosticSink& diagnostics);

}  // namespace ramus
