// How budgeted axes end (GrammarOptions::AxisEnds): tips of their own length, last branch nodes
// of their own, single-internode laterals with a budget of their own, and the automatic choice
// between that model and one length model for every internode by the distance of grown trees.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "infer/skeleton/branch_rules.h"
#include "infer/skeleton/fidelity.h"
#include "infer/skeleton/rule_clustering.h"
#include "infer/skeleton/skeleton_grammar.h"
#include "skeleton_fixtures.h"

using namespace ramus;
using namespace ramus::skeleton_infer;
using skeleton_test::of;
using skeleton_test::ratio;
using AxisEnds = GrammarOptions::AxisEnds;

TEST_CASE("axis ends: measures are recorded to four significant digits", "[skeleton_infer]") {
  // Twelve whip internodes of 0.3 sum to 3.5999999999999996; a regrown budget exp(1.281) is
  // 3.6004. Both are 3.6 at the resolution of the grammar's numbers.
  double whip = 0;
  for (int k = 0; k < 12; ++k) whip += 0.3;
  CHECK(whip != 3.6);
  CHECK(to_resolution(whip) == to_resolution(3.6));
  CHECK(to_resolution(std::exp(1.281)) == to_resolution(3.6));
  CHECK(to_resolution(3.61) != to_resolution(3.6));
  CHECK(to_resolution(0.0) == 0.0);
  CHECK(to_resolution(-12.3456) == Approx(-12.35));
  CHECK(ks_distance({to_resolution(whip), to_resolution(whip)}, {to_resolution(std::exp(1.281))}) ==
        0);
}

TEST_CASE("axis ends: single-internode laterals get a budget of their own", "[skeleton_infer]") {
  std::vector<BudgetSample> s;
  for (int k = 0; k < 30; ++k) {
    BudgetSample b;
    b.log_length = std::log(0.5 + 0.01 * k);
    b.depth = k % 5;
    const bool single = k % 3 == 0;
    b.single = single;
    b.log_axis = single ? std::log(3.6) : std::log(6.0 + 0.1 * (k % 7));
    s.push_back(b);
  }
  const LateralBudget f = fit_lateral_budget(s);
  CHECK(f.p_single == Approx(10.0 / 30));
  CHECK(f.single.samples == 10);
  CHECK(f.branching.samples == 20);
  CHECK(std::exp(f.single.c0) == Approx(3.6).epsilon(1e-6));
  CHECK(f.single.sd < 1e-6);
  CHECK(std::exp(f.branching.lo) >= 6.0 - 1e-9);
  // One kind alone: the probability says which.
  for (auto& b : s) b.single = false;
  CHECK(fit_lateral_budget(s).p_single == 0);
  for (auto& b : s) b.single = true;
  CHECK(fit_lateral_budget(s).p_single == 1);
  CHECK(fit_lateral_budget({}).p_single == 0);
}

TEST_CASE("axis ends: last branch nodes are grouped apart when both parts are large enough",
          "[skeleton_infer]") {
  const Skeleton tree = skeleton_test::grow_example("examples/trees/weeping.ramus", 1);
  const BranchRules rules = extract_branch_rules(tree);
  ClusterOptions o;
  o.split_last = true;
  const std::vector<RuleGroup> groups = cluster_rules(rules, o);
  std::size_t split = 0, total = 0;
  for (const RuleGroup& g : groups) {
    total += g.count;
    if (!g.split) continue;
    ++split;
    CHECK(g.count >= kMinSplitRules);
    for (const RuleCluster& c : g.clusters) {
      for (std::uint32_t m : c.members) CHECK(ends_axis(rules, rules.rules[m]) == g.last);
    }
  }
  CHECK(split >= 2);  // the weeping tree's scaffold apices that fork into whips
  // Every rule with a parent is in exactly one group, split or not.
  std::size_t with_parent = 0;
  for (const Internode& in : rules.internodes) with_parent += in.parent != kNone ? 1 : 0;
  CHECK(total == with_parent);
  o.split_last = false;
  for (const RuleGroup& g : cluster_rules(rules, o)) CHECK_FALSE(g.split);
}

TEST_CASE("axis ends: own tips regrow the weeping tree's whips and crown", "[skeleton_infer]") {
  // Shared lengths drew the whips (3.6 m tips, 64% of the internodes) from the scaffold's
  // ratios: branch-length KS 0.62, crown 1.73 and height 1.54 times the input.
  const Skeleton tree = skeleton_test::grow_example("examples/trees/weeping.ramus", 11);
  GrammarOptions o;
  o.calibration_seeds = 4;
  o.axis_ends = AxisEnds::own;
  const InferredGrammar g = infer_grammar(tree, o);
  std::string messages;
  CHECK(skeleton_test::grammar_checks(g.text, messages));
  CHECK(g.axis_ends == AxisEnds::own);
  CHECK(g.text.find("clamp(r - l, ") != std::string::npos);     // a last branch node's tip
  CHECK(g.text.find("uniform(0, 1) < ") != std::string::npos);  // single or branching lateral
  const auto c = skeleton_test::regrow_and_compare(tree, g.text, "weeping_own.ramus", 10);
  INFO("branch length KS " << of(c, Measure::BranchLength).ks << ", crown "
                           << ratio(of(c, Measure::CrownExtent)) << ", height "
                           << ratio(of(c, Measure::Height)));
  CHECK(of(c, Measure::BranchLength).ks < 0.35);
  CHECK(ratio(of(c, Measure::CrownExtent)) > 0.8);
  CHECK(ratio(of(c, Measure::CrownExtent)) < 1.25);
  CHECK(ratio(of(c, Measure::Height)) > 0.8);
  CHECK(ratio(of(c, Measure::Height)) < 1.25);

  o.axis_ends = AxisEnds::shared;
  const InferredGrammar shared = infer_grammar(tree, o);
  CHECK(shared.axis_ends == AxisEnds::shared);
  CHECK(shared.text.find("clamp(r - l, ") == std::string::npos);
  const auto d = skeleton_test::regrow_and_compare(tree, shared.text, "weeping_shared.ramus", 10);
  CHECK(of(d, Measure::BranchLength).ks > of(c, Measure::BranchLength).ks);
}

TEST_CASE("axis ends: automatic keeps the model whose grown trees are closer", "[skeleton_infer]") {
  for (const char* example : {"examples/trees/weeping.ramus", "examples/trees/conifer.ramus"}) {
    const Skeleton tree = skeleton_test::grow_example(example, 11);
    GrammarOptions o;
    o.calibration_seeds = 2;
    const InferredGrammar g = infer_grammar(tree, o);
    INFO(example << ": own " << g.distance_own << ", shared " << g.distance_shared);
    REQUIRE(g.distance_own >= 0);
    REQUIRE(g.distance_shared >= 0);
    CHECK(g.axis_ends == (g.distance_shared < g.distance_own ? AxisEnds::shared : AxisEnds::own));
    // The distance is what grown_distance measures for the text kept.
    const double kept = g.axis_ends == AxisEnds::own ? g.distance_own : g.distance_shared;
    CHECK(grown_distance(g.text, tree, 2) == Approx(kept));
    // Same input, same grammar.
    CHECK(infer_grammar(tree, o).text == g.text);
  }
  // Without calibration (nothing grown) automatic means own.
  const Skeleton tree = skeleton_test::grow_example("examples/trees/weeping.ramus", 11);
  const InferredGrammar g = infer_grammar(tree, GrammarOptions{});
  CHECK(g.axis_ends == AxisEnds::own);
  CHECK(g.distance_own < 0);
}
