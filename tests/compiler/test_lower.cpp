// Lowering: symbols, splitting of undeclared names, slots, settings, params and -D, the IR dump.
#include <catch2/catch.hpp>

#include "engine_helpers.h"

using namespace ramus;
using ramus::test::grammar_of;

TEST_CASE("lower: turtle symbols have fixed ids and names are split per letter", "[lower]") {
  ir::Grammar g = grammar_of("module Apex(x), Bud; lsystem t { axiom FF Apex(1) AB(2) Bud F; }");
  CHECK(g.find_symbol("F") == 0);
  CHECK(g.find_symbol("%") == int(ir::kCut));
  CHECK(g.find_symbol("Apex") >= ir::kTurtleSymbolCount);
  CHECK(g.find_symbol("AB") == -1);
  ModuleString s = axiom_string(g);
  CHECK(to_text(g, s) == "FF Apex(1)AB(2)Bud F");
  REQUIRE(s.size() == 7);
  CHECK(s.nparams(3) == 0);  // arguments attach to the last letter
  CHECK(s.nparams(4) == 1);
  CHECK(g.symbols[g.find_symbol("B")].arity == 1);
  CHECK(g.symbols[0].arity == 0);
}

TEST_CASE("lower: settings, consts and params", "[lower]") {
  const std::string src = R"(
    const a = 30, b = a / 2;
    param n = 4, s = 7;
    lsystem t { derive n; seed s; angle b; step 0.5; width 2; width_decay 0.5;
                tropism 0, 1, 0; elasticity 0.25; max_depth 4; axiom A; })";
  ir::Grammar g = grammar_of(src);
  CHECK(g.settings.derive == 4);
  CHECK(g.settings.seed == 7);
  CHECK(g.settings.angle == 15);
  CHECK(g.settings.step == 0.5);
  CHECK(g.settings.width == 2);
  CHECK(g.settings.width_decay == 0.5);
  CHECK(g.settings.tropism[1] == 1);
  CHECK(g.settings.elasticity == 0.25);
  CHECK(g.settings.max_depth == 4);
  GrowOptions o;
  o.defines = {{"n", 6}};
  o.seed = 99;
  ir::Grammar g2 = grammar_of(src, o);
  CHECK(g2.settings.derive == 6);
  CHECK(g2.settings.seed == 99);
  o.defines = {{"a", 1}};
  CHECK_THROWS_WITH(grammar_of(src, o), Catch::Contains("const"));
  o.defines = {{"zz", 1}};
  CHECK_THROWS_WITH(grammar_of(src, o), Catch::Contains("zz"));
}

TEST_CASE("lower: the system is chosen by name", "[lower]") {
  const std::string src = "lsystem a { axiom A; } lsystem b { axiom B; }";
  CHECK(grammar_of(src).name == "a");
  GrowOptions o;
  o.system = "b";
  CHECK(grammar_of(src, o).name == "b");
  o.system = "c";
  CHECK_THROWS_WITH(grammar_of(src, o), Catch::Contains("no lsystem named 'c'"));
}

TEST_CASE("lower: the IR dump shows slots, bytecode and tables", "[lower][golden]") {
  const std::string src = R"(const r = 2;
lsystem t {
  ignore +;
  axiom A(1);
  B < A(x) : x > 0 && x < r -> (0.5) A(x * r) | (0.5) F;
  interpret A(x) -> F(x);
})";
  ir::Grammar g = grammar_of(src);
  const std::string expected =
      "lsystem t\n"
      "settings derive=0 seed=0 angle=90 step=1 width=1 width_decay=0.707 tropism=0,0,-1 "
      "elasticity=0 max_depth=8\n"
      "const r = 2\n"
      "symbol 16 A arity=1\n"
      "symbol 17 B arity=0\n"
      "ignored +\n"
      "axiom A({const 1})\n"
      "production 0 rewrite (test.ramus:5:3) slots=1\n"
      "  B < A($0) : {load $0; const 0; gt; jump_if_false @10; load $0; const 2; lt; const 0; ne; "
      "jump @11; const 0}\n"
      "  -> ({const 0.5}) A({load $0; const 2; mul})\n"
      "  -> ({const 0.5}) F\n"
      "production 1 interpret (test.ramus:6:3) slots=1\n"
      "  A($0)\n"
      "  -> F({load $0})\n";
  CHECK(ir::dump(g) == expected);
}

TEST_CASE("lower: a module takes at most 64 arguments", "[lower]") {
  auto with_args = [](int n) {
    std::string args;
    for (int k = 0; k < n; ++k) args += (k ? ", " : "") + std::to_string(k);
    return "lsystem m { axiom A; A -> B(" + args + "); }";
  };
  CHECK_NOTHROW(grammar_of(with_args(64)));
  CHECK_THROWS_WITH(grammar_of(with_args(65)),
                    Catch::Contains("65 arguments") && Catch::Contains("at most 64"));
}
