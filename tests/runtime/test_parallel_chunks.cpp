// The runtime's std::thread run_chunks_parallel (runtime/parallel_chunks_threads.cpp, linked here
// ahead of the TBB one): every chunk runs exactly once, and a derivation is the same string on
// any number of threads.
#include <atomic>
#include <catch2/catch.hpp>
#include <vector>

#include "compiler/derive.h"
#include "compiler/parallel_chunks.h"
#include "compiler/pipeline.h"

TEST_CASE("parallel chunks: every chunk runs exactly once", "[runtime]") {
  for (int threads : {0, 1, 2, 3, 8}) {
    for (std::size_t n : {1u, 2u, 7u, 100u}) {
      std::vector<std::atomic<int>> runs(n);
      ramus::run_chunks_parallel(n, threads, [&](std::size_t c) { runs[c].fetch_add(1); });
      INFO("threads " << threads << ", chunks " << n);
      for (std::size_t c = 0; c < n; ++c) REQUIRE(runs[c].load() == 1);
    }
  }
}

TEST_CASE("parallel chunks: a derivation does not depend on the thread count", "[runtime]") {
  ramus::SourceManager sm;
  ramus::DiagnosticSink diags;
  const ramus::ir::Grammar g = ramus::lower_text("stochastic.ramus", R"(
    lsystem p { seed 5; axiom A; A -> (0.5) A B | (0.5) B A A; B -> (0.3) A | (0.7) B; })",
                                                 {}, sm, diags);
  ramus::DeriveOptions d;
  d.steps = 19;
  d.threads = 1;
  const ramus::ModuleString one = ramus::derive(g, d);
  REQUIRE(one.size() > 100000);  // several chunks of 32768 modules
  for (int threads : {2, 3, 0}) {
    d.threads = threads;
    INFO("threads " << threads);
    CHECK(ramus::derive(g, d) == one);
  }
}
