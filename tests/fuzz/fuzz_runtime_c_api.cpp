// Fuzz target for the embeddable runtime's C API (runtime/ramus_runtime.h, docs/runtime.md), the
// entry point of shipped .rmb files: any bytes either load or give NULL with a message; a grammar
// that loads grows a few steps (or fails with a message) and every getter answers in range and
// refuses out of range. Nothing may throw across the C boundary, crash or leak.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "runtime/ramus_runtime.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  char err[128];
  err[0] = '\0';
  ramus_grammar* g = ramus_load(data, size, err, sizeof err);
  if (!g) {
    if (std::strlen(err) == 0) std::abort();  // a failure always says why
    return 0;
  }
  // Few steps: the runtime has no module limit of its own, and the growth of a grammar is
  // exponential in its steps; the derivation's own limits are fuzzed through decode_rmb.
  const int steps = std::min(ramus_grammar_steps(g), 2);
  err[0] = '\0';
  ramus_skeleton* s = ramus_grow(g, steps, ramus_grammar_seed(g), err, sizeof err);
  if (!s) {
    if (std::strlen(err) == 0) std::abort();
  } else {
    double xyz[3], r;
    const std::size_t nodes = ramus_node_count(s), organs = ramus_organ_count(s);
    for (std::size_t i = 0; i < nodes; ++i) {
      if (ramus_node_position(s, i, xyz) != 0 || ramus_node_radius(s, i, &r) != 0) std::abort();
      const std::int64_t p = ramus_node_parent(s, i);
      if (p < -1 || p >= std::int64_t(nodes)) std::abort();
    }
    for (std::size_t i = 0; i < organs; ++i) {
      if (ramus_organ_position(s, i, xyz) != 0 || ramus_organ_size(s, i, &r) != 0) std::abort();
    }
    if (ramus_node_position(s, nodes, xyz) != -1 || ramus_organ_size(s, organs, &r) != -1 ||
        ramus_node_parent(s, nodes) != -1) {
      std::abort();
    }
    ramus_free_skeleton(s);
  }
  // steps < -1 must be refused with a message, not derived.
  ramus_skeleton* bad = ramus_grow(g, -5, 0, err, sizeof err);
  if (bad) std::abort();
  ramus_free_grammar(g);
  return 0;
}
