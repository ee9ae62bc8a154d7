// Derivation: parallel rewriting of a ModuleString with an ir::Grammar (docs/engine.md).
//
// One pass applies one production table (rewrite, decompose or interpret) to every module at
// once: the first production in file order whose predecessor, contexts and guard match wins,
// a stochastic production picks an alternative from the module's stream, and a module no
// production matches is copied. A pass runs in two sweeps over fixed chunks of the input --
// choose (and count the output), then write at prefix-summed offsets -- on as many threads as
// asked; the chunks do not depend on the thread count and neither does the output.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "compiler/ir.h"
#include "compiler/module_string.h"

namespace ramus {

namespace derive_plan {
struct PassPlan;
}

struct DeriveError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct DeriveOptions {
  std::optional<int> steps;           // default: the grammar's `derive N`
  std::optional<std::uint64_t> seed;  // default: the grammar's `seed S`
  std::uint64_t max_modules = 100'000'000;
  std::uint64_t max_bytes = 0;  // memory guard; 0: 80% of physical memory
  int threads = 0;              // 0: all hardware threads
};

struct DeriveStats {
  int steps = 0;
  double seconds = 0;                // total derivation time
  std::size_t peak_bytes = 0;        // largest string + working tables held during one pass
  std::vector<std::size_t> lengths;  // string length after the axiom (index 0) and each step
};

// The axiom as a string (its arguments are constant).
ModuleString axiom_string(const ir::Grammar& g);

// Derives the grammar's string: decomposition of the axiom, then for each step rewriting,
// decomposition and the cut. Throws DeriveError naming the production and step on failure.
ModuleString derive(const ir::Grammar& g, const DeriveOptions& options,
                    DeriveStats* stats = nullptr);

// Buffers one pass leaves to the next (derive() keeps one for all its passes): the choices of
// each chunk's modules that were not decided by their symbol alone, in module order (sized
// without zero-filling: the choose sweep writes before it reads).
struct PassScratch {
  PassScratch();
  ~PassScratch();
  PassScratch(const PassScratch&) = delete;
  PassScratch& operator=(const PassScratch&) = delete;
  std::vector<PodVector<std::uint32_t>> choices;
  // What the passes plan from the grammar alone, made by the first pass (for its grammar).
  std::unique_ptr<derive_plan::PassPlan> plan;
};

// What one pass needs to know besides the table.
struct PassInfo {
  std::uint64_t seed = 0;
  std::uint64_t key = 0;  // stream key: step * 512 + phase (docs/language.md, Randomness)
  std::string where;      // "step 3", "decomposition after step 3", ...
  std::uint64_t max_modules = 100'000'000;
  std::uint64_t max_bytes = 0;
  int threads = 0;
  std::size_t* peak_bytes = nullptr;
  PassScratch* scratch = nullptr;  // null: the pass uses buffers of its own
};

// Applies table `kind` once to `in`, writing `out`. Returns false (and leaves `out` alone) when
// no module matched. With `origins`, origins->at(i) is replaced by the origin of each output
// module (the input module it came from, traced through `origins` itself).
bool apply_pass(const ir::Grammar& g, ir::Kind kind, const ModuleString& in, ModuleString& out,
                const PassInfo& info, std::vector<std::uint32_t>* origins = nullptr);

// Removes, for every cut symbol `%`, the cut and the rest of its branch up to (not including)
// the `]` that closes it. Returns false if the string holds no cut.
bool apply_cut(ModuleString& s);

// Throws DeriveError when a `]` of `s` closes no branch (compiler/bracket_balance.h).
void check_branches(const ir::Grammar& g, const ModuleString& s, ir::Kind kind,
                    const std::string& where);

// 80% of physical memory, the default of the memory guard.
std::uint64_t default_memory_limit();

}  // namespace ramus
