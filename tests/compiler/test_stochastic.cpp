// Stochastic productions: draws keyed by (seed, step, position), so the string depends on the
// seed only -- not on the thread count -- and ABOP 1.27's invariant holds for every draw.
#include <catch2/catch.hpp>
#include <map>
#include <vector>

#include "compiler/derive_plan.h"
#include "compiler/expr_vm.h"
#include "engine_helpers.h"

using namespace ramus;
using ramus::test::derive_of;
using ramus::test::grammar_of;

namespace {
// ABOP fig. 1.27 (p. 28): three alternatives of probability 1/3 each.
const char* kFig127 = R"(
  lsystem f127 { seed 7; angle 25.7; axiom F;
    F -> (0.33) F [ + F ] F [ - F ] F | (0.33) F [ + F ] F | (0.34) F [ - F ] F; })";

std::size_t count(const ModuleString& s, ir::SymbolId sym) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < s.size(); ++i) n += s.symbol(i) == sym;
  return n;
}
}  // namespace

TEST_CASE("stochastic: ABOP 1.27 keeps length = (5 #F - 3) / 2", "[stochastic][abop]") {
  ir::Grammar g = grammar_of(kFig127);
  for (int n = 0; n <= 6; ++n) {
    ModuleString s = derive_of(g, n);
    const std::size_t f = count(s, ir::SymbolId(ir::TurtleOp::Forward));
    CHECK(2 * s.size() == 5 * f - 3);
  }
}

TEST_CASE("stochastic: same seed same string, other seeds other strings", "[stochastic]") {
  GrowOptions a, b;
  a.seed = 11;
  b.seed = 12;
  ir::Grammar ga = grammar_of(kFig127, a), ga2 = grammar_of(kFig127, a),
              gb = grammar_of(kFig127, b);
  ModuleString sa = derive_of(ga, 5), sa2 = derive_of(ga2, 5), sb = derive_of(gb, 5);
  CHECK(sa == sa2);
  CHECK_FALSE(sa == sb);
  // The seed setting of the grammar is used when no override is given.
  ir::Grammar g7 = grammar_of(kFig127);
  DeriveOptions d;
  d.steps = 5;
  d.seed = 7;
  CHECK(derive(g7, d) == derive_of(g7, 5));
}

TEST_CASE("stochastic: one thread and two threads give identical strings", "[stochastic]") {
  ir::Grammar g = grammar_of(kFig127);
  ModuleString one = derive_of(g, 9, 1), two = derive_of(g, 9, 2);
  REQUIRE(one.size() > 150000);  // several chunks of the parallel pass
  CHECK(one == two);
}

TEST_CASE("stochastic: alternatives are drawn with their probabilities", "[stochastic]") {
  ir::Grammar g = grammar_of(R"(
    lsystem p { axiom A A A A A A A A A A A A A A A A A A A A;
      A -> (0.2) B | (0.8) C; B -> A; C -> A; })");
  std::map<std::string, int> seen;
  std::size_t b = 0, total = 0;
  for (int n = 1; n <= 401; n += 2) {  // odd steps: every A has just been rewritten
    ModuleString s = derive_of(g, n);
    b += count(s, ir::SymbolId(g.find_symbol("B")));
    total += s.size();
  }
  const double share = double(b) / double(total);
  CHECK(share > 0.17);
  CHECK(share < 0.23);
}

TEST_CASE("stochastic: uniform and normal draw from the module's stream", "[stochastic]") {
  ir::Grammar g = grammar_of(R"(
    lsystem u { seed 3; axiom A A A; A -> B(uniform(2, 4)) C(normal(0, 1)); })");
  ModuleString s1 = derive_of(g, 1), s2 = derive_of(g, 1);
  CHECK(s1 == s2);
  for (std::size_t i = 0; i < s1.size(); i += 2) {
    CHECK(s1.param(i, 0) >= 2);
    CHECK(s1.param(i, 0) < 4);
  }
  CHECK(s1.param(0, 0) != s1.param(2, 0));  // positions draw from different streams
}

TEST_CASE("stochastic: a pass's hashed stream prefix gives Rng::stream", "[stochastic]") {
  for (std::uint64_t seed : {0ull, 7ull, ~0ull}) {
    for (std::uint64_t key : {0ull, 512ull, 512ull * 9 + 3}) {
      const std::uint64_t prefix = stream_prefix(seed, key);
      for (std::uint64_t b : {0ull, 1ull, 123457ull}) {
        Rng x = stream_from_prefix(prefix, b), y = Rng::stream(seed, key, b);
        CHECK(x.next_u64() == y.next_u64());
        CHECK(x.next_u64() == y.next_u64());
      }
    }
  }
}

// derive_plan::pick_weighted (the constant-weight path, without a branch on the draw) must take
// the alternative the sequential scan of Pass::pick takes for every draw: the first k with
// u < w[k] after the weights before it were subtracted, else the last positive weight.
TEST_CASE("stochastic: the branch-free weighted pick takes the scan's alternative",
          "[stochastic]") {
  auto scan = [](const std::vector<double>& w, double sum, Rng rng) {
    double u = rng.uniform01() * sum;
    for (std::uint32_t k = 0; k < w.size(); ++k) {
      if (u < w[k]) return k;
      u -= w[k];
    }
    for (std::uint32_t k = std::uint32_t(w.size()); k-- > 0;) {
      if (w[k] > 0) return k;
    }
    return 0u;
  };
  const std::vector<std::vector<double>> cases = {
      {0.33, 0.33, 0.34}, {0.5, 0.5}, {0, 1, 0}, {1, 0}, {0.1, 0.2, 0.3, 0.4, 1e-300, 0}, {3}};
  for (const auto& w : cases) {
    std::vector<double> ws = w;
    double sum = 0;
    for (double v : w) sum += v;
    ws.push_back(sum);
    const auto n = std::uint32_t(w.size());
    const std::uint32_t fallback = derive_plan::last_positive(ws.data(), n);
    std::map<std::uint32_t, int> seen;
    for (std::uint64_t b = 0; b < 20000; ++b) {
      const Rng rng = Rng::stream(11, 512, b);
      const std::uint32_t k = derive_plan::pick_weighted(ws.data(), n, fallback, rng);
      REQUIRE(k == scan(w, sum, rng));
      ++seen[k];
    }
    for (std::uint32_t k = 0; k < n; ++k) {
      CHECK((seen[k] == 0 || w[k] > 0));           // a zero weight is never taken
      if (w[k] >= 0.01 * sum) CHECK(seen[k] > 0);  // nor is a weight of 1e-300 in 20000 draws
    }
  }
  // A draw whose u passes every weight (rounding at the top end) takes the fallback.
  const double top[] = {0.25, 0.0, 0.25, 0.0, 0.25};  // sum 0.25 + 0.25 < u
  CHECK(derive_plan::last_positive(top, 4) == 2);
}
