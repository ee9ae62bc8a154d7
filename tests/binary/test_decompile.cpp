// `decompile` (formats/rmb/rmb_decompile.h): for every example, the text decompiled from its .rmb
// checks cleanly, is a fixed point of the formatter, and lowers to a grammar that derives the
// same string for the same seed; expressions come back with the fewest parentheses and compile
// to the same bytecode.
#include <catch2/catch.hpp>

#include "../cli/cli_runner.h"
#include "formats/rmb/rmb_codec.h"
#include "formats/rmb/rmb_decompile.h"
#include "grammar/format.h"
#include "grammar/parser.h"
#include "rmb_test_util.h"

using namespace ramus;

namespace {

struct Relowered {
  ir::Grammar g;
  std::size_t warnings = 0;
};

Relowered relower(const std::string& text) {
  SourceManager sm;
  DiagnosticSink diags;
  Relowered r{lower_text("decompiled.ramus", text, GrowOptions{}, sm, diags), 0};
  for (const Diagnostic& d : diags.all()) r.warnings += d.severity == Severity::Warning;
  return r;
}

std::string formatted(const std::string& text) {
  SourceManager sm;
  DiagnosticSink diags;
  const ast::File f = parse(sm, sm.add("decompiled.ramus", text), diags);
  REQUIRE(!diags.has_errors());
  return format_file(f, sm);
}

std::size_t source_warnings(const std::string& relative) {
  SourceManager sm;
  DiagnosticSink diags;
  lower_file(std::string(RAMUS_SOURCE_DIR) + "/" + relative, GrowOptions{}, sm, diags);
  std::size_t n = 0;
  for (const Diagnostic& d : diags.all()) n += d.severity == Severity::Warning;
  return n;
}

}  // namespace

TEST_CASE("binary: every example decompiles to text that derives the same", "[binary]") {
  const auto files = test::example_grammars();
  REQUIRE(files.size() >= 20);
  for (const std::string& file : files) {
    INFO(file);
    const ir::Grammar g = test::lower_example(file);
    const ir::Grammar back = decode_rmb(encode_rmb(g));
    const std::string text = decompile(back);
    INFO(text);
    CHECK(formatted(text) == text);  // `ramus fmt` is a no-op on it
    const Relowered again = relower(text);
    CHECK(again.warnings <= source_warnings(file));
    CHECK(again.g.productions.size() == g.productions.size());
    REQUIRE(again.g.codes.size() == g.codes.size());
    for (std::size_t c = 0; c < g.codes.size(); ++c) {
      CHECK(ir::dump_code(again.g, ir::CodeId(c)) == ir::dump_code(g, ir::CodeId(c)));
    }
    const ModuleString a = test::derive_steps(g, g.settings.derive);
    CHECK(a.size() > 0);
    CHECK(test::derive_steps(again.g, again.g.settings.derive) == a);
    // And the same again from the decompiled grammar's own .rmb.
    CHECK(decompile(decode_rmb(encode_rmb(again.g))) == text);
  }
}

TEST_CASE("binary: stochastic examples decompile to the same derivation for other seeds",
          "[binary]") {
  for (const char* file : {"examples/trees/broadleaf.ramus", "examples/trees/weeping.ramus"}) {
    INFO(file);
    const ir::Grammar g = test::lower_example(file);
    const ir::Grammar again = relower(decompile(decode_rmb(encode_rmb(g)))).g;
    for (std::uint64_t seed : {1ull, 42ull, 987654321ull}) {
      CHECK(test::derive_with_seed(g, seed) == test::derive_with_seed(again, seed));
    }
  }
}

TEST_CASE("binary: expressions come back as infix with the fewest parentheses", "[binary]") {
  const std::string source =
      "lsystem ex {\n"
      "  derive 4;\n"
      "  axiom A(1, 2);\n"
      "  A(x, y) : x < 10 && (y > 0 || !(x == 3)) -> A(x + 1, (x - y) - (x - (y - 1)))\n"
      "    B(-(x ^ 2), (-x) ^ 2, x ^ y ^ 2, (x ^ y) ^ 2, x > 2 ? y : x * (y + 1),\n"
      "      min(x, max(y, 2)) % 3, x / (y * 2), x * -1, (x > 1 ? 1 : 2) + 3, -x - -y);\n"
      "  B(a, b, c, d, e, f, g, h, i, j) -> ;\n"
      "}\n";
  SourceManager sm;
  DiagnosticSink diags;
  const ir::Grammar g = lower_text("ex.ramus", source, GrowOptions{}, sm, diags);
  const std::string text = decompile(decode_rmb(encode_rmb(g)));
  INFO(text);
  for (const char* expected :
       {"A(x, y) : x < 10 && (y > 0 || !(x == 3)) ->", "A(x + 1, x - y - (x - (y - 1)))", "-x ^ 2",
        "(-x) ^ 2", "x ^ y ^ 2", "(x ^ y) ^ 2", "x > 2 ? y : x * (y + 1)", "min(x, max(y, 2)) % 3",
        "x / (y * 2)", "x * -1", "(x > 1 ? 1 : 2) + 3", "-x - -y"}) {
    CHECK(text.find(expected) != std::string::npos);
  }
  const ir::Grammar again = relower(text).g;
  REQUIRE(again.codes.size() == g.codes.size());
  for (std::size_t c = 0; c < g.codes.size(); ++c) {
    CHECK(ir::dump_code(again, ir::CodeId(c)) == ir::dump_code(g, ir::CodeId(c)));
  }
  CHECK(test::derive_steps(again, 4) == test::derive_steps(g, 4));
}

// The decompiler prints every constant as a literal, `-3.141592653589793` for `-pi`, so a
// negated constant must compile as the negative literal does: one constant (fuzz_roundtrip_rmb
// found `l + -pi` and `l * 0 + -+0.5` compiling to a constant and a negation).
TEST_CASE("binary: a negated constant compiles as its negative literal does", "[binary]") {
  auto codes = [](const std::string& args) {
    SourceManager sm;
    DiagnosticSink diags;
    const ir::Grammar g = lower_text("neg.ramus",
                                     "const k = 3;\nlsystem t {\n  derive 1;\n  axiom A(1);\n"
                                     "  A(x) -> B(" +
                                         args + ");\n  B(a, b, c, d) -> ;\n}\n",
                                     GrowOptions{}, sm, diags);
    std::string all;
    for (std::size_t c = 0; c < g.codes.size(); ++c) all += ir::dump_code(g, ir::CodeId(c));
    return std::make_pair(all, g);
  };
  const auto [named, g] = codes("x + -pi, x * -+0.5, x - -(+2), x + -k");
  CHECK(named == codes("x + -3.141592653589793, x * -0.5, x - -2, x + -3").first);
  const std::string text = decompile(decode_rmb(encode_rmb(g)));
  INFO(text);
  const ir::Grammar again = relower(text).g;
  REQUIRE(again.codes.size() == g.codes.size());
  for (std::size_t c = 0; c < g.codes.size(); ++c) {
    CHECK(ir::dump_code(again, ir::CodeId(c)) == ir::dump_code(g, ir::CodeId(c)));
  }
}

TEST_CASE("binary: formal names fall back to p0, p1 without production texts", "[binary]") {
  ir::Grammar g = test::lower_example("examples/abop/param_p42.ramus");
  for (ir::Production& p : g.productions) p.text.clear();
  const std::string text = decompile(g);
  CHECK(text.find("A(p0, p1) : p1 <= 3 -> A(p0 * 2, p0 + p1);") != std::string::npos);
  CHECK(test::derive_steps(relower(text).g, 5) == test::derive_steps(g, 5));
}

TEST_CASE("binary: ramus decompile writes text that ramus fmt leaves unchanged", "[binary][cli]") {
  using namespace cli_test;
  TempDir tmp;
  const fs::path rmb = tmp.path / "broadleaf.rmb", out = tmp.path / "broadleaf.ramus";
  REQUIRE(
      run_ramus({"-q", "build", std::string(RAMUS_SOURCE_DIR) + "/examples/trees/broadleaf.ramus",
                 "--target", "binary", "-o", rmb.string()})
          .status == 0);
  REQUIRE(run_ramus({"-q", "decompile", rmb.string(), "-o", out.string()}).status == 0);
  const std::string text = slurp(out);
  CHECK(text.find("lsystem broadleaf {") != std::string::npos);
  CHECK(run_ramus({"check", out.string()}).status == 0);
  CHECK(run_ramus({"fmt", "--check", out.string()}).status == 0);
  CHECK(run_ramus({"decompile", rmb.string()}).out == text);  // stdout without -o
  // A damaged file is refused with its byte offset.
  std::string bytes = slurp(rmb);
  bytes[bytes.size() / 2] ^= 0x40;
  write_text(rmb, bytes);
  const CliResult bad = run_ramus({"decompile", rmb.string()});
  CHECK(bad.status == 1);
  CHECK(bad.out.find("byte ") != std::string::npos);
}

TEST_CASE("binary: contexts, declared modules, ignore and kinds decompile", "[binary]") {
  const std::string source =
      "module Apex(x), Bud(x);\n"
      "param k = 0.25;\n"
      "lsystem ctx {\n"
      "  derive 3;\n"
      "  seed 11;\n"
      "  angle 22.5;\n"
      "  ignore + -;\n"
      "  axiom Bud(1)[+Apex(2)]Apex(3);\n"
      "  Bud(a) < Apex(b) > [Bud(c)] : a + b > 1 -> (0.5) Apex(b * k) | (0.5) Apex(uniform(0, "
      "b));\n"
      "  decompose Apex(x) : x < 0.01 -> F(x);\n"
      "  interpret Bud(n) -> ~(n);\n"
      "}\n";
  SourceManager sm;
  DiagnosticSink diags;
  const ir::Grammar g = lower_text("ctx.ramus", source, GrowOptions{}, sm, diags);
  const std::string text = decompile(decode_rmb(encode_rmb(g)));
  INFO(text);
  for (const char* expected :
       {"module Bud(p0), Apex(p0);", "param k = 0.25;", "ignore + -;", "angle 22.5;",
        "Bud(a) < Apex(b) > [Bud(c)] : a + b > 1 -> (0.5) Apex(b * k)",
        "| (0.5) Apex(uniform(0, b));", "decompose Apex(x) : x < 0.01 -> F(x);",
        "interpret Bud(n) -> ~(n);"}) {
    CHECK(text.find(expected) != std::string::npos);
  }
  CHECK(formatted(text) == text);
  const ir::Grammar again = relower(text).g;
  for (std::size_t c = 0; c < g.codes.size(); ++c) {
    CHECK(ir::dump_code(again, ir::CodeId(c)) == ir::dump_code(g, ir::CodeId(c)));
  }
  for (std::uint64_t seed : {0ull, 5ull, 77ull}) {
    DeriveOptions d;
    d.steps = 3;
    d.seed = seed;
    d.threads = 1;
    CHECK(derive(again, d) == derive(g, d));
  }
}
