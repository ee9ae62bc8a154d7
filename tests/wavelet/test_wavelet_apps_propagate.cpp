// Geometry propagation (Friedman & Stamos 2013, IV-C): K trees from one grammar, each with its
// own seed and a perturbed axiom, pairwise distinct and reproducible from the seed.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "../cli/cli_runner.h"
#include "../compiler/engine_helpers.h"
#include "formats/rmb/rmb_codec.h"
#include "infer/wavelet/propagate.h"

using namespace ramus;
using namespace ramus::wavelet;

namespace {

// ABOP fig. 2.6a (deterministic: only the axiom perturbation makes trees differ).
const char* kMonopodial = R"(
const r1 = 0.9, r2 = 0.6, a0 = 45, a2 = 45, d = 137.5, wr = 0.707;
lsystem monopodial {
  derive 6;
  axiom A(1, 0.15);
  A(l, w) -> !(w)F(l)[&(a0)B(l * r2, w * wr)]/(d)A(l * r1, w * wr);
  B(l, w) -> !(w)F(l)[-(a2)$C(l * r2, w * wr)]C(l * r1, w * wr);
  C(l, w) -> !(w)F(l)[+(a2)$B(l * r2, w * wr)]B(l * r1, w * wr);
})";

// Stochastic, and an axiom without arguments: only the seed makes trees differ.
const char* kStochastic = R"(
lsystem bush { derive 4; angle 25.7; axiom F;
  F -> (0.33) F [ + F ] F [ - F ] F | (0.33) F [ + F ] F | (0.34) F [ - F ] F; })";

Skeleton grow(const ir::Grammar& g) {
  ModuleString s = derive(g, DeriveOptions{});
  TurtleOptions t;
  t.seed = g.settings.seed;
  t.steps = g.settings.derive;
  return interpret(g, s, t);
}

std::vector<double> positions(const Skeleton& s) {
  std::vector<double> v;
  for (const SkeletonNode& n : s.nodes) {
    v.push_back(n.position.x), v.push_back(n.position.y), v.push_back(n.position.z);
    v.push_back(n.radius);
  }
  return v;
}

}  // namespace

TEST_CASE("propagate: K trees are pairwise distinct and the same seed gives the same trees",
          "[wavelet][propagate]") {
  for (const char* text : {kMonopodial, kStochastic}) {
    const ir::Grammar g = test::grammar_of(text);
    for (std::uint64_t seed : {1, 2, 99}) {
      PropagateOptions o;
      o.seed = seed;
      std::set<std::vector<double>> seen;
      for (std::uint64_t k = 0; k < 8; ++k) {
        const Skeleton a = grow(propagate_grammar(g, k, o).grammar);
        const Skeleton b = grow(propagate_grammar(g, k, o).grammar);
        CHECK(positions(a) == positions(b));
        CHECK(seen.insert(positions(a)).second);
      }
      // Another propagation seed gives other trees.
      PropagateOptions other = o;
      other.seed = seed + 1000;
      CHECK(seen.count(positions(grow(propagate_grammar(g, 0, other).grammar))) == 0);
    }
  }
}

TEST_CASE("propagate: the axiom arguments move by at most the jitter and nothing else changes",
          "[wavelet][propagate]") {
  const ir::Grammar g = test::grammar_of(kMonopodial);
  const ModuleString original = axiom_string(g);
  for (double jitter : {0.0, 0.05, 0.3}) {
    for (std::uint64_t k = 0; k < 50; ++k) {
      PropagateOptions o;
      o.seed = 3;
      o.jitter = jitter;
      const PropagatedGrammar p = propagate_grammar(g, k, o);
      const ModuleString axiom = axiom_string(p.grammar);
      REQUIRE(axiom.size() == original.size());
      for (std::size_t m = 0; m < axiom.size(); ++m) {
        REQUIRE(axiom.nparams(m) == original.nparams(m));
        for (std::uint32_t i = 0; i < axiom.nparams(m); ++i) {
          const double v = original.param(m, i), w = axiom.param(m, i);
          CHECK(std::abs(w - v) <= jitter * std::abs(v) + 1e-15);
        }
      }
      CHECK(p.perturbed_args == (jitter == 0 ? 0 : 2));
      CHECK(p.grammar.settings.seed == propagated_seed(3, k));
      CHECK(p.grammar.productions.size() == g.productions.size());
      // The productions' expressions are untouched: the original codes are still there as they
      // were, and the grammar stays valid for the binary format.
      for (std::size_t c = 0; c < g.codes.size(); ++c) {
        CHECK(p.grammar.codes[c].value == g.codes[c].value);
      }
      CHECK_NOTHROW(decode_rmb(encode_rmb(p.grammar)));
    }
  }
  CHECK_THROWS_AS(propagate_grammar(g, 0, PropagateOptions{1, 1.0}), std::invalid_argument);
  CHECK_THROWS_AS(propagate_grammar(g, 0, PropagateOptions{1, -0.1}), std::invalid_argument);
}

TEST_CASE("propagate: zero arguments stay zero and jitter 0 keeps the axiom",
          "[wavelet][propagate]") {
  const ir::Grammar g = test::grammar_of("lsystem z { axiom F(0) +(0) F(2); F(x) -> F(x) F(x); }");
  PropagateOptions o;
  o.jitter = 0.5;
  const ModuleString axiom = axiom_string(propagate_grammar(g, 4, o).grammar);
  CHECK(axiom.param(0, 0) == 0);
  CHECK(axiom.param(1, 0) == 0);
  CHECK(axiom.param(2, 0) != 2);
  o.jitter = 0;
  const ModuleString same = axiom_string(propagate_grammar(g, 4, o).grammar);
  CHECK(same.param(2, 0) == 2);
}

TEST_CASE("propagate cli: K meshes, pairwise distinct, byte-identical for the same seed",
          "[wavelet][propagate][cli]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(RAMUS_BINARY_DIR) / "wavelet_apps_propagate";
  fs::remove_all(dir);
  const fs::path grammar = cli_test::write_text(dir / "mono.ramus", kMonopodial);
  auto run = [&](const std::string& args) { return cli_test::run_ramus_shell(args); };
  const cli_test::CliResult a =
      run("propagate " + grammar.string() + " -n 4 -o " + (dir / "a").string() + " --seed 7");
  REQUIRE(a.status == 0);
  CHECK(a.out.find("tree_003.glb") != std::string::npos);
  REQUIRE(run("-q propagate " + grammar.string() + " -n 4 -o " + (dir / "b").string() + " --seed 7")
              .status == 0);
  std::set<std::string> distinct;
  for (const char* name : {"tree_000.glb", "tree_001.glb", "tree_002.glb", "tree_003.glb"}) {
    const std::string bytes = cli_test::slurp(dir / "a" / name);
    REQUIRE(!bytes.empty());
    CHECK(bytes.compare(0, 4, "glTF") == 0);
    CHECK(bytes == cli_test::slurp(dir / "b" / name));
    distinct.insert(bytes);
  }
  CHECK(distinct.size() == 4);
  CHECK(!fs::exists(dir / "a" / "tree_004.glb"));
  // The meshes pass the Khronos glTF validator (tests/gltf/validate.js exits 1 on any issue).
  const std::string validate =
      "node " + cli_test::shell_quote(RAMUS_SOURCE_DIR "/tests/gltf/validate.js") + " " +
      cli_test::shell_quote((dir / "a" / "tree_000.glb").string()) + " " +
      cli_test::shell_quote((dir / "a" / "tree_003.glb").string()) + " >/dev/null 2>&1";
  CHECK(std::system(validate.c_str()) == 0);

  // The perturbed grammars themselves, in the binary format.
  REQUIRE(
      run("-q propagate " + grammar.string() + " -n 2 -o " + (dir / "r").string() + " --format rmb")
          .status == 0);
  const ir::Grammar r0 = decode_rmb(cli_test::slurp(dir / "r" / "tree_000.rmb"));
  const ir::Grammar r1 = decode_rmb(cli_test::slurp(dir / "r" / "tree_001.rmb"));
  CHECK(r0.settings.seed != r1.settings.seed);
  CHECK(axiom_string(r0).param(0, 0) != axiom_string(r1).param(0, 0));
}

TEST_CASE("propagate cli: nothing to perturb and bad arguments are errors",
          "[wavelet][propagate][cli]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(RAMUS_BINARY_DIR) / "wavelet_apps_propagate_bad";
  fs::remove_all(dir);
  auto run = [&](const std::string& args) { return cli_test::run_ramus_shell(args); };
  const fs::path fixed =
      cli_test::write_text(dir / "fixed.ramus", "lsystem f { derive 2; axiom F; F -> F[+F]F; }");
  const cli_test::CliResult same =
      run("propagate " + fixed.string() + " -n 2 -o " + (dir / "out").string());
  CHECK(same.status == 1);
  CHECK(same.out.find("are the same tree") != std::string::npos);
  // One tree is always distinct from the others.
  CHECK(run("-q propagate " + fixed.string() + " -n 1 -o " + (dir / "one").string()).status == 0);
  const fs::path broken = cli_test::write_text(dir / "broken.ramus", "lsystem b { axiom F(; }");
  CHECK(run("propagate " + broken.string() + " -n 2 -o " + (dir / "x").string()).status == 1);
  CHECK(run("propagate " + fixed.string() + " -n 0 -o " + (dir / "x").string()).status == 2);
  CHECK(run("propagate " + fixed.string() + " -n 2 -o " + (dir / "x").string() + " --jitter 1")
            .status == 2);
  CHECK(run("propagate " + fixed.string() + " -n 2 -o " + (dir / "x").string() + " --format stl")
            .status == 2);
  CHECK(run("propagate " + fixed.string() + " -o " + (dir / "x").string()).status == 2);
}
