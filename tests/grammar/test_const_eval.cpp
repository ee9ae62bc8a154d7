// Constant folding (grammar/const_eval.h): the arithmetic the checks and the lowering share.
#include <catch2/catch.hpp>
#include <cmath>

#include "grammar/const_eval.h"
#include "grammar/loader.h"

using namespace ramus;

namespace {

// Parses `const v = <expr>;` and returns the expression.
ast::Expr expr_of(const std::string& text) {
  SourceManager sm;
  DiagnosticSink sink;
  Program p = load_program_text("t.ramus", "const v = " + text + ";", sm, sink);
  REQUIRE_FALSE(sink.has_errors());
  REQUIRE(p.files.size() == 1);
  return std::get<ast::ConstDecl>(p.files[0].decls.at(0)).bindings.at(0).value;
}

std::optional<double> fold(const std::string& text) {
  return fold_constant(expr_of(text), [](std::string_view n) -> std::optional<double> {
    if (n == "k") return 4.0;
    return std::nullopt;
  });
}

}  // namespace

TEST_CASE("const_eval: arithmetic with precedence and associativity", "[const_eval]") {
  CHECK(*fold("1 + 2 * 3") == 7);
  CHECK(*fold("(1 + 2) * 3") == 9);
  CHECK(*fold("2 ^ 3 ^ 2") == 512);  // right associative
  CHECK(*fold("-2 ^ 2") == -4);      // unary binds looser than ^
  CHECK(*fold("7 % 3") == 1);
  CHECK(*fold("10 - 4 - 3") == 3);
  CHECK(*fold("k * 2") == 8);
  CHECK(*fold("1 < 2 ? 10 : 20") == 10);
  CHECK(*fold("!(1 > 2) && true") == 1);
}

TEST_CASE("const_eval: trigonometry is in degrees", "[const_eval]") {
  CHECK(*fold("sin(30)") == Approx(0.5));
  CHECK(*fold("cos(180)") == Approx(-1));
  CHECK(*fold("atan2(1, 1)") == Approx(45));
  CHECK(*fold("acos(0)") == Approx(90));
  CHECK(*fold("clamp(5, 0, 2)") == 2);
  CHECK(*fold("sign(-3) + round(2.5) + min(1, 2)") == 3);
  CHECK(*fold("pi") == Approx(3.14159265358979));
}

TEST_CASE("const_eval: what is not constant says why", "[const_eval]") {
  auto lookup = [](std::string_view) -> std::optional<double> { return std::nullopt; };
  FoldResult r = evaluate_constant(expr_of("1 + q"), lookup);
  REQUIRE(r.error);
  CHECK(r.error->kind == FoldError::Kind::UnknownName);
  r = evaluate_constant(expr_of("uniform(0, 1)"), lookup);
  REQUIRE(r.error);
  CHECK(r.error->kind == FoldError::Kind::Random);
  r = evaluate_constant(expr_of("sqrt(-1)"), lookup);
  REQUIRE(r.error);
  CHECK(r.error->kind == FoldError::Kind::NotFinite);
  r = evaluate_constant(expr_of("1 / 0"), lookup);
  REQUIRE(r.error);
  CHECK(r.error->kind == FoldError::Kind::NotFinite);
  // Short-circuit: the division is never evaluated.
  CHECK(*fold("false && 1 / 0 > 1") == 0);
  CHECK_FALSE(fold("foo(1)"));
}
