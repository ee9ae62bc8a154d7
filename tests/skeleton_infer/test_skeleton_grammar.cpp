// Inferred grammars: they check, are in canonical format, stay within the rule budget, are
// deterministic, and regrow trees whose distributions are close (KS) to the input's; degenerate
// skeletons give small grammars or clear errors.
#include <catch2/catch.hpp>

#include "core/rng.h"
#include "infer/skeleton/fidelity.h"
#include "infer/skeleton/skeleton_grammar.h"
#include "skeleton_fixtures.h"

using namespace ramus;
using namespace ramus::skeleton_infer;
using skeleton_test::add_node;

namespace {

double ks_of(const std::vector<MeasureComparison>& c, Measure m) {
  for (const auto& x : c) {
    if (x.measure == m) return x.ks;
  }
  return 1;
}

void require_valid_grammar(const InferredGrammar& g, std::size_t max_rules) {
  std::string messages;
  INFO(g.text);
  CHECK(skeleton_test::grammar_checks(g.text, messages));
  INFO(messages);
  CHECK(skeleton_test::formatted(g.text) == g.text);
  CHECK(g.alternatives <= max_rules);
}

}  // namespace

TEST_CASE("grammar: probabilities are exact six-place decimals summing to 1", "[skeleton_infer]") {
  Skeleton s;
  // A trunk with three forks: every rule its own, the grammar still small and valid.
  const auto r = add_node(s, {0, 0, 0}, kNoParent, 0.3);
  auto f = add_node(s, {0, 0, 1}, r, 0.3);
  for (int k = 0; k < 3; ++k) {
    add_node(s, s.nodes[f].position + Vec3{0.5, 0.1 * k, 0.4}, f, 0.1);
    f = add_node(s, s.nodes[f].position + Vec3{0, 0.05, 1}, f, 0.25 - 0.05 * k);
  }
  const InferredGrammar g = infer_grammar(s, {});
  require_valid_grammar(g, 32);
  CHECK(g.branch_nodes == 3);
  CHECK(g.internodes == 7);
}

TEST_CASE("grammar: deterministic for a seed", "[skeleton_infer]") {
  const Skeleton tree = skeleton_test::grow_example("examples/trees/broadleaf.ramus", 3);
  GrammarOptions o;
  o.cluster.seed = 5;
  CHECK(infer_grammar(tree, o).text == infer_grammar(tree, o).text);
}

TEST_CASE("grammar: from broadleaf, regrown trees match over several seeds", "[skeleton_infer]") {
  for (std::uint64_t seed : {1, 2, 3}) {
    const Skeleton tree = skeleton_test::grow_example("examples/trees/broadleaf.ramus", seed);
    GrammarOptions o;
    o.source_name = "broadleaf.ramus";
    const InferredGrammar g = infer_grammar(tree, o);
    require_valid_grammar(g, 32);
    const auto c = skeleton_test::regrow_and_compare(tree, g.text, "broadleaf_inferred.ramus", 8);
    for (const auto& x : c) INFO(measure_name(x.measure) << " KS " << x.ks);
    // Bounds measured with margin (docs/skeleton-inference.md gives the measured values).
    CHECK(ks_of(c, Measure::BranchingAngle) < 0.25);
    CHECK(ks_of(c, Measure::BranchLength) < 0.45);
    CHECK(ks_of(c, Measure::BranchOrder) < 0.3);
    CHECK(ks_of(c, Measure::Azimuth) < 0.3);
    // Radius ratios on a few exact values are drawn as two-point distributions (a fitted
    // log-normal gave KS 0.66).
    CHECK(ks_of(c, Measure::RadiusRatio) < 0.15);
  }
}

TEST_CASE("grammar: rule budget is met by fewer clusters", "[skeleton_infer]") {
  const Skeleton tree = skeleton_test::grow_example("examples/trees/conifer.ramus", 1);
  for (int budget : {2, 4, 8, 12, 32}) {
    GrammarOptions o;
    o.max_rules = budget;
    o.cluster.max_clusters = 8;
    const InferredGrammar g = infer_grammar(tree, o);
    require_valid_grammar(g, std::size_t(budget));
  }
}

TEST_CASE("grammar: degenerate skeletons", "[skeleton_infer]") {
  Skeleton one;
  add_node(one, {0, 0, 0}, kNoParent);
  CHECK_THROWS_AS(infer_grammar(one, {}), InferError);
  CHECK_THROWS_AS(infer_grammar(Skeleton{}, {}), InferError);
  // No branching: a single production that draws the one internode.
  Skeleton chain;
  auto p = add_node(chain, {0, 0, 0}, kNoParent, 0.2);
  for (int k = 1; k <= 5; ++k) p = add_node(chain, {0, 0, double(k)}, p, 0.2);
  const InferredGrammar g = infer_grammar(chain, {});
  require_valid_grammar(g, 32);
  CHECK(g.productions == 1);
  const Skeleton regrown = skeleton_test::grow_text("chain.ramus", g.text, 1);
  CHECK(regrown.size() == 2);
  CHECK(regrown.total_length() == Approx(5));
  // A cycle is reported, not looped over.
  Skeleton cyc;
  add_node(cyc, {0, 0, 0}, 1);
  add_node(cyc, {0, 0, 1}, 0);
  CHECK_THROWS_AS(infer_grammar(cyc, {}), ExtractError);
}

TEST_CASE("grammar: random trees where every node is unique give valid small grammars",
          "[skeleton_infer]") {
  for (std::uint64_t seed = 1; seed <= 25; ++seed) {
    Rng rng(seed);
    Skeleton s;
    add_node(s, {0, 0, 0}, kNoParent, 0.3);
    const int n = 2 + int(rng.below(400));
    for (int i = 1; i < n; ++i) {
      const auto parent = std::uint32_t(rng.below(std::uint64_t(i)));
      const Vec3 q = s.nodes[parent].position +
                     Vec3{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-0.2, 1)};
      add_node(s, q, parent, rng.uniform(0, 0.3));
    }
    GrammarOptions o;
    o.cluster.seed = seed;
    const InferredGrammar g = infer_grammar(s, o);
    require_valid_grammar(g, 32);
    // It grows without a derivation error.
    CHECK_NOTHROW(skeleton_test::grow_text("random_inferred.ramus", g.text, seed));
  }
}

TEST_CASE("grammar: tip hazard fit", "[skeleton_infer]") {
  // Tips with probability 0.2 at every depth: beta near 0, p near 0.2.
  Rng rng(9);
  std::vector<double> d, y;
  for (int i = 0; i < 5000; ++i) {
    d.push_back(double(rng.below(10)));
    y.push_back(rng.uniform01() < 0.2 ? 1 : 0);
  }
  TipHazard h = fit_tip_hazard(d, y);
  CHECK(1 / (1 + std::exp(-h.alpha)) == Approx(0.2).margin(0.03));
  CHECK(std::abs(h.beta) < 0.05);
  // Perfect separation (tips only at depth 5): finite, and steep.
  d.clear(), y.clear();
  for (int k = 0; k <= 5; ++k) {
    for (int i = 0; i < 20; ++i) d.push_back(k), y.push_back(k == 5 ? 1 : 0);
  }
  h = fit_tip_hazard(d, y);
  CHECK(std::isfinite(h.alpha));
  CHECK(std::isfinite(h.beta));
  CHECK(1 / (1 + std::exp(-(h.alpha + 5 * h.beta))) > 0.95);
  CHECK(1 / (1 + std::exp(-(h.alpha + 4 * h.beta))) < 0.05);
}
