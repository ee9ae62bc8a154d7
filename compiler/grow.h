// Growing a tree from a grammar file in one call: load (with imports) -> check -> lower ->
// derive -> interpret with the turtle -> Skeleton. What `ramus build`, `ramus preview`,
// `ramus scan` and the tests use when they only need the tree.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/skeleton.h"
#include "grammar/diagnostic.h"
#include "grammar/source.h"

namespace ramus {

struct GrowOptions {
  std::string system;                  // lsystem block; empty: the first one of the root file
  std::optional<int> steps;            // overrides `derive N`
  std::optional<std::uint64_t> seed;   // overrides `seed S`
  std::vector<std::pair<std::string, double>> defines;  // -D name=value (params only)
  std::uint64_t max_modules = 100'000'000;
};

// Thrown when the grammar has errors (they are in the DiagnosticSink) or derivation fails
// (the message names the production and the step).
struct GrowError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

Skeleton grow_file(const std::string& path, const GrowOptions& options, SourceManager& sources,
                   DiagnosticSink& diagnostics);

}  // namespace ramus
