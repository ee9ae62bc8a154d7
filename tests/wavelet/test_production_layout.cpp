// The productions of an inferred grammar are written in `ramus fmt` layout directly
// (wrap_modules, grammar/format.h); over many synthetic trees and grids the whole file equals its
// formatted self, and short and long productions wrap as the formatter wraps them.
#include <catch2/catch.hpp>

#include "fractal_cloud.h"
#include "grammar/diagnostic.h"
#include "grammar/format.h"
#include "grammar/parser.h"
#include "grammar/source.h"
#include "infer/wavelet/infer_grammar.h"

using namespace ramus;
using namespace ramus::wavelet;

namespace {

std::string formatted(const std::string& text) {
  SourceManager sm;
  DiagnosticSink sink;
  const std::uint32_t id = sm.add("x.ramus", text);
  const ast::File file = parse(sm, id, sink);
  REQUIRE_FALSE(sink.has_errors());
  return format_file(file, sm);
}

}  // namespace

TEST_CASE("production layout: inferred grammars are in fmt layout over many trees and grids",
          "[wavelet][layout]") {
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    for (int grid : {16, 32, 64}) {
      INFO("seed " << seed << ", grid " << grid);
      WaveletInferOptions o;
      o.grid = grid;
      o.seed = seed;
      const std::string text =
          infer_wavelet_grammar(test::fractal_tree_cloud(seed, 4 + int(seed % 3)), o).ramus_text;
      CHECK(formatted(text) == text);
    }
  }
}

TEST_CASE("production layout: wrapping matches the formatter", "[wavelet][layout]") {
  Rng rng(11);
  for (int trial = 0; trial < 200; ++trial) {
    // A random bracketed successor of 1-40 modules with argument texts of varied length.
    std::vector<std::string> modules;
    int depth = 0;
    const int n = 1 + int(rng.below(40));
    for (int k = 0; k < n; ++k) {
      if (rng.uniform01() < 0.2) {
        modules.push_back("[");
        ++depth;
      }
      modules.push_back("V(" + std::to_string(rng.below(100000)) + ", l * 0." +
                        std::to_string(rng.below(1000000)) + ", s * 0.5, w)");
      if (depth > 0 && rng.uniform01() < 0.3) {
        modules.push_back("]");
        --depth;
      }
    }
    while (depth-- > 0) modules.push_back("]");
    const std::string head = "  V(x, l, s, w) @ (0.5, " + std::to_string(trial) + ") ->";
    const std::string production = wrap_modules(head, modules, ";");
    const std::string text =
        "module V(x, l, s, w);\n\nlsystem t {\n  select nearest(x, l / s);\n"
        "  axiom V(1, 1, 1, 1);\n" +
        production + "}\n";
    INFO(production);
    CHECK(formatted(text) == text);
  }
}
