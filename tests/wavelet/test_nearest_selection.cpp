// `select nearest` (docs/language.md, "Rule-space selection"): the derivation picks the keyed
// production nearest to the query point, ties by file order, falls back to the first unkeyed
// match, and the keys survive the .rmb format.
#include <catch2/catch.hpp>
#include <string>

#include "../compiler/engine_helpers.h"
#include "core/rng.h"
#include "formats/rmb/rmb_codec.h"
#include "grammar/check.h"
#include "grammar/format.h"
#include "grammar/parser.h"

using namespace ramus;
using ramus::test::derive_text;
using ramus::test::grammar_of;

namespace {

// A: three keyed productions on a line; the successor names the winner.
std::string line_grammar(double x) {
  return "module P0, P1, P2;\n"
         "lsystem s {\n"
         "  select nearest(x);\n"
         "  axiom A(" +
         std::to_string(x) +
         ");\n"
         "  A(x) @ (0) -> P0;\n"
         "  A(x) @ (10) -> P1;\n"
         "  A(x) @ (4) -> P2;\n"
         "}\n";
}

}  // namespace

TEST_CASE("nearest selection picks the production whose key is nearest", "[nearest]") {
  CHECK(derive_text(line_grammar(-3), 1) == "P0");
  CHECK(derive_text(line_grammar(1.9), 1) == "P0");
  CHECK(derive_text(line_grammar(2.1), 1) == "P2");
  CHECK(derive_text(line_grammar(6.9), 1) == "P2");
  CHECK(derive_text(line_grammar(7.1), 1) == "P1");
  CHECK(derive_text(line_grammar(100), 1) == "P1");
}

TEST_CASE("nearest selection breaks ties by file order", "[nearest]") {
  // x = 2 and x = 7 are at equal distance from two keys: the earlier production wins.
  CHECK(derive_text(line_grammar(2), 1) == "P0");
  CHECK(derive_text(line_grammar(7), 1) == "P1");
  // Equal keys: always the first.
  const std::string equal =
      "module P0, P1;\nlsystem s { select nearest(x); axiom A(5);\n"
      "  A(x) @ (1) -> P0; A(x) @ (1) -> P1; }\n";
  CHECK(derive_text(equal, 1) == "P0");
}

TEST_CASE("nearest selection measures Euclidean distance in several dimensions", "[nearest]") {
  // Query (3, 4): key (0, 0) is at 5, key (3, -2) at 6, key (7, 4) at 4: the last wins although
  // it is farther along the first axis alone.
  const std::string g =
      "module P0, P1, P2;\nlsystem s { select nearest(a, b * 2); axiom A(3, 2);\n"
      "  A(a, b) @ (0, 0) -> P0;\n  A(a, b) @ (3, -2) -> P1;\n  A(a, b) @ (7, 4) -> P2; }\n";
  CHECK(derive_text(g, 1) == "P2");
}

TEST_CASE("nearest selection matches a brute-force oracle over random keys", "[nearest]") {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    Rng rng(seed);
    const int n = 2 + int(rng.uniform(0, 12));
    std::string text = "lsystem s {\n  select nearest(x, y);\n  axiom";
    std::vector<std::pair<double, double>> queries;
    for (int q = 0; q < 8; ++q) {
      // Keys and queries on a coarse lattice, so that ties happen.
      queries.push_back({std::floor(rng.uniform(0, 5)), std::floor(rng.uniform(0, 5))});
      text += " A(" + std::to_string(queries.back().first) + ", " +
              std::to_string(queries.back().second) + ")";
    }
    text += ";\n";
    std::vector<std::pair<double, double>> keys;
    for (int k = 0; k < n; ++k) {
      keys.push_back({std::floor(rng.uniform(0, 5)), std::floor(rng.uniform(0, 5))});
      text += "  A(x, y) @ (" + std::to_string(keys.back().first) + ", " +
              std::to_string(keys.back().second) + ") -> B(" + std::to_string(k) + ");\n";
    }
    text += "}\n";
    std::string expected;
    for (const auto& [qx, qy] : queries) {
      int best = 0;
      double bd = 1e300;
      for (int k = 0; k < n; ++k) {
        const double d = (qx - keys[k].first) * (qx - keys[k].first) +
                         (qy - keys[k].second) * (qy - keys[k].second);
        if (d < bd) {
          bd = d;
          best = k;
        }
      }
      expected += "B(" + std::to_string(best) + ")";
    }
    INFO("seed " << seed << "\n" << text);
    CHECK(derive_text(text, 1) == expected);
  }
}

TEST_CASE("nearest selection honours guards and contexts and falls back to unkeyed productions",
          "[nearest]") {
  // The nearest key (0) is guarded out for x > 1, so the next nearest wins.
  const std::string guarded =
      "module P0, P1, Q;\nlsystem s { select nearest(x); axiom A(2) A(0.5);\n"
      "  A(x) : x <= 1 @ (0) -> P0;\n  A(x) @ (10) -> P1;\n}\n";
  CHECK(derive_text(guarded, 1) == "P1 P0");
  // Without a keyed match, the first unkeyed match in file order applies; a keyed match wins
  // over an earlier unkeyed one.
  const std::string fallback =
      "module K, U1, U2;\nlsystem s { select nearest(x); axiom A(1) A(5);\n"
      "  A(x) -> U1;\n  A(x) -> U2;\n  A(x) : x > 3 @ (0) -> K;\n}\n";
  CHECK(derive_text(fallback, 1) == "U1 K");
  // Context: the keyed production with the right context only matches before a B.
  const std::string context =
      "module P0, P1;\nlsystem s { select nearest(x); axiom A(0) B A(0);\n"
      "  A(x) > B @ (0) -> P0;\n  A(x) @ (5) -> P1;\n}\n";
  CHECK(derive_text(context, 1) == "P0 B P1");
}

TEST_CASE("nearest selection is deterministic and independent of the thread count", "[nearest]") {
  std::string text = "lsystem s { select nearest(x); seed 7; axiom A(0);\n";
  text += "  A(x) @ (0) -> (0.5) A(x + uniform(0, 3)) A(x + 1) | (0.5) A(x + 2);\n";
  text += "  A(x) @ (2) -> A(x - 1) [ A(x + uniform(-1, 1)) ];\n";
  text += "  A(x) @ (4) -> A(x * 0.5);\n}\n";
  ir::Grammar g = grammar_of(text);
  const ModuleString one = ramus::test::derive_of(g, 9, 1);
  const ModuleString many = ramus::test::derive_of(g, 9, 4);
  CHECK(one.size() > 50);
  CHECK(to_text(g, one) == to_text(g, many));
  CHECK(to_text(g, one) == to_text(g, ramus::test::derive_of(grammar_of(text), 9, 2)));
}

TEST_CASE("nearest selection keys appear in the IR dump and survive the binary format",
          "[nearest]") {
  const std::string text = line_grammar(6.5);
  ir::Grammar g = grammar_of(text);
  REQUIRE(g.selection == ir::Selection::Nearest);
  REQUIRE(g.productions.size() == 3);
  CHECK(g.productions[1].key == std::vector<double>{10});
  CHECK(g.productions[1].query.size() == 1);
  const std::string d = ir::dump(g);
  CHECK(d.find("selection nearest") != std::string::npos);
  CHECK(d.find("@ (10 ~ {load $0})") != std::string::npos);
  const std::string bytes = encode_rmb(g);
  ir::Grammar back = decode_rmb(bytes);
  CHECK(ir::dump(back) == d);
  CHECK(to_text(back, ramus::test::derive_of(back, 1)) == "P2");
  // A grammar without `select nearest` encodes no key fields (older files stay byte-identical).
  ir::Grammar first = grammar_of("lsystem s { axiom A(1); A(x) -> B; }\n");
  CHECK(decode_rmb(encode_rmb(first)).productions[0].key.empty());
}
