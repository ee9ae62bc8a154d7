// The trees bench_pieces measures: its piece set and the assembly options of tree k, shared with
// the tests that check what the benchmark reports (tests/pieces/test_output_piece_stream.cpp).
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "backends/pieces/pieces.h"
#include "core/rng.h"
#include "grammar/check.h"
#include "grammar/loader.h"

namespace ramus::bench {

inline const char* kBenchPieceSet = R"(
pieces bench {
  rim hexagon(radius: 0.3);
  piece I = tube(length: 2, taper: 0.97);
  piece Y = fork(length: 2, angle: 30, taper: 0.92);
  root I;
  I.top -> I 0.6 | Y 0.4;
  Y.left -> I 0.7 | Y 0.3;
  Y.right -> I 0.7 | Y 0.3;
  twist any;
  depth 200;
}
)";

inline pieces::PieceSet lower_bench_piece_set() {
  SourceManager sources;
  DiagnosticSink diags;
  const Program program = load_program_text("bench.ramus", kBenchPieceSet, sources, diags);
  check_program(program, sources, diags);
  pieces::PieceSet set = pieces::lower_pieces(program, sources, {}, diags);
  if (diags.has_errors()) {
    std::fprintf(stderr, "bench_pieces: the bench piece set does not lower\n");
    std::exit(1);
  }
  return set;
}

// Tree k of a run with `seed`: 200..2,000 pieces, drawn from one generator in tree order
// (call in order k = 0, 1, ... with the same `rng`, seeded Rng(seed)).
inline pieces::AssembleOptions bench_tree_options(Rng& rng, std::uint64_t seed, std::size_t k) {
  pieces::AssembleOptions ao;
  ao.seed = seed * 1000003 + k;
  ao.max_pieces = std::uint32_t(200 + rng.below(1801));
  return ao;
}

}  // namespace ramus::bench
