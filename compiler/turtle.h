// The 3D turtle (Prusinkiewicz & Lindenmayer, ABOP ch. 1.5 and 2.2): interprets a derived string
// as a Skeleton. Conventions (docs/language.md, Turtle): z up; the frame H (heading), L (left),
// U (up) with U = H x L starts at H = (0,0,1), L = (-1,0,0); `+` turns towards L, which is a
// counter-clockwise turn in the front view (seen from -y).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "compiler/derive.h"
#include "compiler/ir.h"
#include "compiler/module_string.h"
#include "core/skeleton.h"

namespace ramus {

struct TurtleOptions {
  std::uint64_t seed = 0;  // the derivation's seed (interpretation rules may draw)
  int steps = 0;           // the derivation's step count (keys the interpretation streams)
  std::uint64_t max_modules = 100'000'000;
  std::uint64_t max_bytes = 0;
  int threads = 0;
};

// Applies the grammar's `interpret` productions (up to max_depth levels, each level a parallel
// pass over the whole string) and walks the result with the turtle. Every node's
// source_module is the index in `s` of the module it came from.
Skeleton interpret(const ir::Grammar& g, const ModuleString& s, const TurtleOptions& options);

// The turtle walk alone, with no interpretation rules. `origins` (optional) maps each module to
// its source index; without it a module is its own source.
Skeleton run_turtle(const ir::Grammar& g, const ModuleString& s,
                    const std::vector<std::uint32_t>* origins = nullptr);

}  // namespace ramus
