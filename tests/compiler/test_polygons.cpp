// The turtle's polygons (ABOP 5.2: `{` `.` `}` and G) and the engine's refusal of a `]` or `}`
// that closes nothing (compiler/bracket_balance.h).
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "compiler/bracket_balance.h"
#include "engine_helpers.h"

using namespace ramus;
using namespace ramus::test;

namespace {

// The message of the DeriveError that `f` throws, or "" when it throws none.
template <typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const DeriveError& e) {
    return e.what();
  }
  return "";
}

ir::SymbolId symbol(const ir::Grammar& g, const std::string& name) {
  const int s = g.find_symbol(name);
  REQUIRE(s >= 0);
  return ir::SymbolId(s);
}

}  // namespace

TEST_CASE("polygons: { . } and G are turtle symbols found by name", "[turtle][polygon]") {
  const ir::Grammar g = grammar_of("lsystem s { axiom {.G.f.}; }");
  CHECK(g.symbols[symbol(g, "{")].turtle == ir::TurtleOp::PolygonBegin);
  CHECK(g.symbols[symbol(g, ".")].turtle == ir::TurtleOp::Vertex);
  CHECK(g.symbols[symbol(g, "}")].turtle == ir::TurtleOp::PolygonEnd);
  CHECK(g.symbols[symbol(g, "G")].turtle == ir::TurtleOp::MoveNoVertex);
  CHECK(ir::polygon_op("A") == ir::TurtleOp::None);
}

TEST_CASE("polygons: . records, G moves without recording, f records inside a polygon",
          "[turtle][polygon]") {
  // A unit square traced three ways: by `.`, by f (ABOP fig. 1.26's leaves) and with a G that
  // must add no vertex.
  for (const char* axiom : {"{.f+.f+.f+.}", "{f+f+f+f}", "{.G+.f+.f+.}"}) {
    INFO(axiom);
    const Skeleton sk = skeleton_of(std::string("lsystem s { angle 90; axiom ") + axiom + "; }", 0);
    REQUIRE(sk.organs.size() == 1);
    const auto& v = sk.organs[0].vertices;
    REQUIRE(v.size() == 4);
    // H starts at +z and + turns towards L = -x: the corners (0,0,0) (0,0,1) (-1,0,1) (-1,0,0),
    // from whichever the recording began at.
    Vec3 sum;
    for (const Vec3& p : v) sum += p;
    CHECK(sum.x == Approx(-2));
    CHECK(sum.y == Approx(0).margin(1e-12));
    CHECK(sum.z == Approx(2));
    CHECK(length(v[2] - v[0]) == Approx(std::sqrt(2.0)));
  }
}

TEST_CASE("polygons: the polygon stack is not the branch stack", "[turtle][polygon]") {
  // ABOP's cordate leaf: polygons opened inside branches collect vertices after the `]`. After n
  // steps each side has n polygons, of which the two youngest have no surface (their axes have
  // not grown: two of their three vertices coincide).
  const Skeleton sk = skeleton_of(
      "lsystem s { angle 10; axiom [A][B]; A -> [+A{.].C.}; B -> [-B{.].C.}; C -> GC; }", 4);
  REQUIRE(sk.organs.size() == 4);
  for (const OrganAnchor& o : sk.organs) CHECK(o.vertices.size() == 3);
  // Nested polygons: the inner one closes first.
  const Skeleton nested = skeleton_of("lsystem s { angle 90; axiom {.f{.f+.f+.}+.f+.}; }", 0);
  REQUIRE(nested.organs.size() == 2);
  CHECK(nested.organs[0].vertices.size() == 3);
  CHECK(nested.organs[1].vertices.size() == 4);
}

TEST_CASE("polygons: a } or . without a polygon, or a { never closed, is an error",
          "[turtle][polygon]") {
  // The checker refuses these in the source; the turtle must refuse them in a string that got
  // past it (an .rmb, the runtime): lower a correct grammar, then break its axiom.
  ir::Grammar g = grammar_of("lsystem s { axiom {.F.F.}; }");
  ir::Grammar no_open = g;
  no_open.axiom[0].symbol = ir::SymbolId(ir::TurtleOp::Forward);
  CHECK(error_of([&] { skeleton_of_grammar(no_open); }).find("`.` records a vertex outside") !=
        std::string::npos);
  ir::Grammar no_close = g;
  no_close.axiom.back().symbol = ir::SymbolId(ir::TurtleOp::Forward);
  CHECK(error_of([&] { skeleton_of_grammar(no_close); }).find("`{` opens a polygon that no `}`") !=
        std::string::npos);
  ir::Grammar stray = grammar_of("lsystem s { axiom F{.F.F.}; }");
  stray.axiom[1].symbol = ir::SymbolId(ir::TurtleOp::Forward);  // `{` -> F: `}` closes nothing
  stray.axiom[2].symbol = ir::SymbolId(ir::TurtleOp::Forward);  // and no `.` outside it
  stray.axiom[4].symbol = ir::SymbolId(ir::TurtleOp::Forward);
  stray.axiom[6].symbol = ir::SymbolId(ir::TurtleOp::Forward);
  CHECK(error_of([&] { skeleton_of_grammar(stray); }).find("`}` closes no polygon (module 7") !=
        std::string::npos);
}

TEST_CASE(
    "brackets: a closing bracket with no open branch stops derivation, naming step and production",
    "[derive][brackets]") {
  ir::Grammar g = grammar_of("lsystem s { derive 2; axiom F; F -> F[+F]F; }");
  CHECK_FALSE(may_unbalance_branches(g, ir::Kind::Rewrite));
  for (ir::SuccModule& m : g.successors) {
    if (m.symbol == ir::kPush) m.symbol = ir::kPop;  // F -> F]+F]F, as an unchecked .rmb may hold
  }
  CHECK(may_unbalance_branches(g, ir::Kind::Rewrite));
  const std::string e = error_of([&] { derive_of(g, 2); });
  INFO(e);
  CHECK(e.find("step 1: `]` at module 1 closes no branch") != std::string::npos);
  CHECK(e.find("written by production `F -> F[+F]F;` (test.ramus:1:32)") != std::string::npos);
  // The axiom too.
  ir::Grammar a = grammar_of("lsystem s { axiom F[F]; }");
  a.axiom[1].symbol = ir::kPop;
  CHECK(error_of([&] { derive_of(a, 0); }).find("the axiom: `]` at module 1 closes no branch") !=
        std::string::npos);
  // And the turtle itself, for a string given to it unbalanced.
  ir::Grammar t = grammar_of("lsystem s { axiom F[+F]; }");
  t.axiom[1].symbol = ir::SymbolId(ir::TurtleOp::Forward);
  const std::string te = error_of([&] { run_turtle(t, axiom_string(t)); });
  CHECK(te.find("interpretation: `]` closes no branch (module 4)") != std::string::npos);
}
