// Derivation semantics: parallel rewriting, first match in file order, parametric productions
// (ABOP p. 42), guards, decomposition, the cut, limits and expression errors.
#include <catch2/catch.hpp>

#include "engine_helpers.h"

using namespace ramus;
using ramus::test::derive_of;
using ramus::test::derive_text;
using ramus::test::grammar_of;

TEST_CASE("derive: algae grows with Fibonacci lengths", "[derive]") {
  const std::string src = "lsystem algae { axiom A; A -> A B; B -> A; }";
  CHECK(derive_text(src, 0) == "A");
  CHECK(derive_text(src, 1) == "AB");
  CHECK(derive_text(src, 4) == "ABAABABA");
  ir::Grammar g = grammar_of(src);
  std::size_t a = 1, b = 1;  // lengths follow Fibonacci numbers
  for (int n = 1; n <= 20; ++n) {
    CHECK(derive_of(g, n).size() == b + a);
    std::size_t c = a + b;
    a = b;
    b = c;
  }
}

// ABOP p. 42, figure 1.32: the first strings of the parametric example, written out in the book.
TEST_CASE("derive: parametric example of ABOP p. 42", "[derive][abop]") {
  const std::string src = R"(
    lsystem p42 {
      axiom B(2) A(4, 4);
      A(x, y) : y <= 3 -> A(x * 2, x + y);
      A(x, y) : y > 3 -> B(x) A(x / y, 0);
      B(x) : x < 1 -> C;
      B(x) : x >= 1 -> B(x - 1);
    })";
  CHECK(derive_text(src, 0) == "B(2)A(4,4)");
  CHECK(derive_text(src, 1) == "B(1)B(4)A(1,0)");
  CHECK(derive_text(src, 2) == "B(0)B(3)A(2,1)");
  CHECK(derive_text(src, 3) == "CB(2)A(4,3)");
  CHECK(derive_text(src, 4) == "CB(1)A(8,7)");
  CHECK(derive_text(src, 5) == "CB(0)B(8)A(1.1428571428571428,0)");
}

TEST_CASE("derive: the first matching production in file order wins", "[derive]") {
  const std::string src = R"(
    lsystem order {
      axiom A(1) A(5);
      A(x) : x > 2 -> B;
      A(x) : x > 0 -> C;
      A(x) -> D;
    })";
  CHECK(derive_text(src, 1) == "CB");
}

TEST_CASE("derive: unmatched modules are copied with their parameters", "[derive]") {
  CHECK(derive_text("lsystem c { axiom X(0.25) A Y(1, 2); A -> B; }", 3) == "X(0.25)BY(1,2)");
}

TEST_CASE("derive: short-circuit logic guards against a division by zero", "[derive][expr]") {
  const std::string src = R"(
    lsystem s { axiom A(0) A(4);
      A(x) : x != 0 && 8 / x > 1 -> B(x);
      A(x) : x == 0 || 1 / x > 100 -> C; })";
  CHECK(derive_text(src, 1) == "CB(4)");
}

TEST_CASE("derive: expressions use degrees and fold constants", "[derive][expr]") {
  const std::string src = R"(
    const half = 0.5, k = 2 * half + 1;
    param scale = 3;
    lsystem e { axiom A(30);
      A(x) -> B(sin(x), atan2(1, 1), k, scale * x, x % 7, 2 ^ 3 ^ 2, -x, x > 1 ? 10 : 20); })";
  CHECK(derive_text(src, 1) == "B(0.49999999999999994,45,2,90,2,512,-30,10)");
  GrowOptions opt;
  opt.defines = {{"scale", 10}};
  ir::Grammar g = grammar_of(src, opt);
  CHECK(to_text(g, derive_of(g, 1)) == "B(0.49999999999999994,45,2,300,2,512,-30,10)");
}

TEST_CASE("derive: decomposition runs after every step until nothing applies", "[derive]") {
  const std::string src = R"(
    lsystem d { axiom A;
      A -> A B;
      decompose B -> C D;
      decompose D -> E;
    })";
  CHECK(derive_text(src, 0) == "A");
  CHECK(derive_text(src, 1) == "ACE");
  CHECK(derive_text(src, 2) == "ACECE");
}

TEST_CASE("derive: a decomposition that never ends is an error", "[derive][errors]") {
  ir::Grammar g = grammar_of("lsystem d { max_depth 5; axiom A; decompose A -> B A; }");
  CHECK_THROWS_WITH(derive_of(g, 0), Catch::Contains("max_depth = 5"));
}

TEST_CASE("derive: the cut removes the rest of its branch", "[derive][cut]") {
  CHECK(derive_text("lsystem c { axiom A [ B % C [ D ] E ] F; }", 0) == "A[B]F");
  CHECK(derive_text("lsystem c { axiom A [ B X C ] F; X -> %; }", 1) == "A[B]F");
  CHECK(derive_text("lsystem c { axiom A X B [ C ] D; X -> %; }", 1) == "A");
}

TEST_CASE("derive: a runaway grammar stops at max-modules naming the step", "[derive][errors]") {
  ir::Grammar g = grammar_of("lsystem r { axiom A; A -> A A; }");
  CHECK_THROWS_WITH(derive_of(g, 30, 0, 1000), Catch::Contains("step 10") &&
                                                   Catch::Contains("1024 modules") &&
                                                   Catch::Contains("--max-modules"));
  CHECK(derive_of(g, 9, 0, 1000).size() == 512);
}

TEST_CASE("derive: the memory guard stops before allocating", "[derive][errors]") {
  ir::Grammar g = grammar_of("lsystem r { axiom A(1); A(x) -> A(x) A(x); }");
  DeriveOptions d;
  d.steps = 40;
  d.max_modules = ~0ull;
  d.max_bytes = 1 << 20;
  CHECK_THROWS_WITH(derive(g, d), Catch::Contains("memory limit") && Catch::Contains("step 16"));
}

TEST_CASE("derive: division by zero names the production and the step", "[derive][errors]") {
  const std::string src =
      "lsystem z {\n"
      "  axiom A(3);\n"
      "  A(x) -> A(x - 1) B(1 / x);\n"
      "}\n";
  ir::Grammar g = grammar_of(src);
  CHECK_NOTHROW(derive_of(g, 3));
  CHECK_THROWS_WITH(derive_of(g, 4),
                    Catch::Contains("division by zero") && Catch::Contains("test.ramus:3:3") &&
                        Catch::Contains("test.ramus:3:22") && Catch::Contains("step 4"));
}

TEST_CASE("derive: non-finite and out-of-domain values are errors", "[derive][errors]") {
  auto fails = [](const std::string& succ, const std::string& why) {
    ir::Grammar g = grammar_of("lsystem z { axiom A(-1); A(x) -> " + succ + "; }");
    CHECK_THROWS_WITH(derive_of(g, 1), Catch::Contains(why) && Catch::Contains("step 1"));
  };
  fails("B(sqrt(x))", "square root of a negative number");
  fails("B(log(x))", "logarithm");
  fails("B(exp(-1000 * x))", "exp overflows");
  fails("B(x ^ 0.5)", "fractional exponent");
  fails("B(asin(2 * x))", "asin");
  fails("B(x % 0)", "modulo by zero");
}

TEST_CASE("derive: a constant division by zero is reported at lowering", "[derive][errors]") {
  CHECK_THROWS_AS(grammar_of("lsystem z { axiom A; A -> B(1 / 0); }"), GrowError);
}

TEST_CASE("derive: zero steps give the axiom", "[derive]") {
  CHECK(derive_text("lsystem z { axiom F(1) [ + A(0.5) ]; A(x) -> B; }", 0) == "F(1)[+A(0.5)]");
}

// A symbol whose first production has no context and no guard is decided by its symbol alone
// (derive.cpp, SymbolPlan): the same grammar with a guard that always holds goes through
// matching instead and must give the same string, draws included, on one thread and on two,
// over several chunks.
TEST_CASE("derive: productions decided by their symbol give what matching gives", "[derive]") {
  auto grammar = [](const std::string& guard_a, const std::string& guard_b) {
    return "lsystem t { seed 5; axiom A(1) B(2);\n"
           "  A(x)" +
           guard_a +
           " -> (0.3) F(x) [ + A(x / 2) ] A(x * uniform(0.9, 1.1))\n"
           "        | (0.7) F(x / 2) A(x / 2) B(x);\n"
           "  B(y)" +
           guard_b + " -> B(y + 1) [ - A(y / 3) ] F(y / 3); }";
  };
  ir::Grammar planned = grammar_of(grammar("", "")),
              matched = grammar_of(grammar(" : x == x", " : y == y"));
  const int steps = 14;
  const ModuleString a = derive_of(planned, steps, 1), b = derive_of(matched, steps, 1);
  REQUIRE(a.size() > 3 * 32768);  // several chunks
  CHECK(a == b);
  CHECK(derive_of(planned, steps, 2) == a);
  CHECK(derive_of(matched, steps, 2) == a);
}

TEST_CASE("derive: an argument written twice is the same value, a random one is drawn twice",
          "[derive][expr]") {
  ir::Grammar g = grammar_of(
      "lsystem t { seed 3; axiom A(3); A(s) -> B(s / 7) B(s / 7) C(uniform(0, 1)) C(uniform(0, "
      "1)); }");
  const ModuleString s = derive_of(g, 1);
  REQUIRE(s.size() == 4);
  CHECK(s.param(0, 0) == 3.0 / 7);
  CHECK(s.param(1, 0) == s.param(0, 0));
  CHECK(s.param(2, 0) != s.param(3, 0));
}
