// The front half of the pipeline as one call: load (with imports) -> check -> lower. Shared by
// grow_file() (compiler/grow.h), `ramus derive` and the benchmarks.
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

struct GrowOptions {
  std::string system;                  // lsystem block; empty: the first one of the root file
  std::optional<int> steps;            // overrides `derive N`
  std::optional<std::uint64_t> seed;   // overrides `seed S`
  std::vector<std::pair<std::string, double>> defines;  // -D name=value (params only)
  std::uint64_t max_modules = 100'000'000;
  std::uint64_t max_bytes = 0;  // memory guard of the derivation (--max-memory); 0: 80% of RAM
};

// Thrown when the grammar has errors (they are in the DiagnosticSink) or derivation fails
// (the message names the production and the step).
struct GrowError : std::runtime_error {
  using std::runtime_error::runtime_error;
};


// Throws GrowError when the grammar has errors (they are in `diagnostics`; the message repeats
// the first) or the options name no lsystem / no param.
ir::Grammar lower_file(const std::string& path, const GrowOptions& options, SourceManager& sources,
                       DiagnosticSink& diagnostics);

// The same for grammar text already in memory (`name` is what diagnostics print).
ir::Grammar lower_text(const std::string& name, const std::string& text, const GrowOptions& options,
                       SourceManager& sources, DiagnosticSink& diagnostics);

// Lowers a program the caller has loaded and checked (with options.defines) without errors.
ir::Grammar lower_checked(const Program& program, const GrowOptions& options,
                          SourceManager& sources, DiagnosticSink& diagnostics);

}  // namespace ramus
