// Regrown trees keep the input's size: total length (the calibration) and crown extent (axis
// length budgets, tortuous internodes drawn kinked), on the bundled grammars, on a zigzag
// skeleton and on a real scan; the tip hazard that the budgets replace still fits and writes.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "../cli/cli_runner.h"
#include "core/rng.h"
#include "infer/skeleton/fidelity.h"
#include "infer/skeleton/skeleton_grammar.h"
#include "skeleton_fixtures.h"

using namespace ramus;
using namespace ramus::skeleton_infer;
using skeleton_test::add_node;
using skeleton_test::of;
using skeleton_test::ratio;

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

TEST_CASE("regrown extent: weeping keeps its total length and branch lengths", "[skeleton_infer]") {
  // The weeping grammar ends its scaffold where the width falls below a threshold; a hazard of
  // depth alone regrew 2.6 to 4 times the length (branch-length KS 0.85).
  for (std::uint64_t seed : {1, 2}) {
    const Skeleton tree = skeleton_test::grow_example("examples/trees/weeping.ramus", seed);
    GrammarOptions o;
    o.calibration_seeds = 4;
    const InferredGrammar g = infer_grammar(tree, o);
    std::string messages;
    CHECK(skeleton_test::grammar_checks(g.text, messages));
    CHECK(skeleton_test::formatted(g.text) == g.text);
    CHECK(g.alternatives <= 32);
    // The axes end by their budgets: a guard on r, a log-normal budget for every lateral.
    CHECK(g.text.find(" && r > ") != std::string::npos);
    CHECK(g.text.find("d + 1, exp(clamp(") != std::string::npos);
    // The input is one tree: its length against the mean over 8 regrown ones.
    Distributions a, b;
    measure(tree, a);
    for (int s = 1; s <= 8; ++s)
      measure(skeleton_test::grow_text("weeping_inferred.ramus", g.text, std::uint64_t(s)), b);
    const auto c = compare(a, b);
    INFO("seed " << seed << " total length ratio " << ratio(of(c, Measure::TotalLength))
                 << " branch length KS " << of(c, Measure::BranchLength).ks);
    CHECK(ratio(of(c, Measure::TotalLength)) > 0.6);
    CHECK(ratio(of(c, Measure::TotalLength)) < 1.6);
    CHECK(of(c, Measure::BranchLength).ks < 0.75);
  }
}

TEST_CASE("regrown extent: without axis budgets the tip hazard ends the axes", "[skeleton_infer]") {
  const Skeleton tree = skeleton_test::grow_example("examples/trees/weeping.ramus", 1);
  GrammarOptions o;
  o.calibration_seeds = 2;
  o.axis_budget = false;
  const InferredGrammar g = infer_grammar(tree, o);
  std::string messages;
  CHECK(skeleton_test::grammar_checks(g.text, messages));
  CHECK(skeleton_test::formatted(g.text) == g.text);
  // The hazard ends in a width or length term (BIC picks length: the whips are long tips).
  CHECK(g.text.find("1e-9))), -30, 30)") != std::string::npos);
  CHECK(g.text.find("N(l, w, o, i, d) ->") != std::string::npos);
  CHECK(g.text.find(" && r > ") == std::string::npos);
}

TEST_CASE("regrown extent: axis budget fit recovers its terms", "[skeleton_infer]") {
  // log L = 1 + 0.5 log l - 0.1 d + normal(0, 0.2); the width carries nothing.
  Rng rng(9);
  std::vector<BudgetSample> s;
  for (int i = 0; i < 3000; ++i) {
    BudgetSample b;
    b.log_length = -2 + 2 * rng.uniform01();
    b.log_width = -4 + 3 * rng.uniform01();
    b.depth = double(rng.below(10));
    b.log_axis = 1 + 0.5 * b.log_length - 0.1 * b.depth + 0.2 * rng.normal();
    s.push_back(b);
  }
  const AxisBudget f = fit_axis_budget(s);
  CHECK(f.samples == s.size());
  CHECK(f.c0 == Approx(1).margin(0.03));
  CHECK(f.cl == Approx(0.5).margin(0.02));
  CHECK(f.cd == Approx(-0.1).margin(0.005));
  CHECK(f.cw == 0);  // left out by the BIC
  CHECK(f.sd == Approx(0.2).margin(0.01));
  // Two axes: too few for any term, the mean alone.
  const AxisBudget two = fit_axis_budget({s[0], s[1]});
  CHECK(two.c0 == Approx((s[0].log_axis + s[1].log_axis) / 2));
  CHECK(two.cl == 0);
  CHECK(two.sd == 0);
  CHECK(fit_axis_budget({}).samples == 0);
}

TEST_CASE("regrown extent: axis budgets keep the bundled trees' crowns", "[skeleton_infer]") {
  // With a tip decided at every internode, the regrown conifer and broadleaf crowns were 1.37
  // times the input's: an axis could jump to twig length and go on branching out there. With
  // axis budgets 1.08 and 1.21 (docs/skeleton-inference.md; the inputs of seeds 1 to 4 against
  // 8 regrown trees here).
  for (const char* path : {"examples/trees/conifer.ramus", "examples/trees/broadleaf.ramus"}) {
    const Skeleton tree = skeleton_test::grow_example(path, 1);
    GrammarOptions o;
    o.calibration_seeds = 4;
    const InferredGrammar g = infer_grammar(tree, o);
    std::string messages;
    CHECK(skeleton_test::grammar_checks(g.text, messages));
    CHECK(g.alternatives <= 32);
    Distributions a, b;
    for (int s = 1; s <= 4; ++s) measure(skeleton_test::grow_example(path, std::uint64_t(s)), a);
    for (int s = 1; s <= 8; ++s)
      measure(skeleton_test::grow_text("budget_inferred.ramus", g.text, std::uint64_t(s)), b);
    const auto c = compare(a, b);
    INFO(path << " crown ratio " << ratio(of(c, Measure::CrownExtent)) << " length ratio "
              << ratio(of(c, Measure::TotalLength)) << " branch length KS "
              << of(c, Measure::BranchLength).ks);
    CHECK(ratio(of(c, Measure::CrownExtent)) > 0.8);
    CHECK(ratio(of(c, Measure::CrownExtent)) < 1.25);
    CHECK(ratio(of(c, Measure::TotalLength)) > 0.75);
    CHECK(ratio(of(c, Measure::TotalLength)) < 1.33);
    CHECK(of(c, Measure::BranchLength).ks < 0.3);
  }
}

TEST_CASE("regrown extent: tip hazard takes the width when it explains the tips",
          "[skeleton_infer]") {
  // Tips exactly where log w < -2, at every depth: the fit separates them by width.
  Rng rng(4);
  std::vector<TipSample> s;
  for (int i = 0; i < 2000; ++i) {
    const double lw = -4 + 4 * rng.uniform01();
    s.push_back({double(rng.below(12)), lw, lw < -2 ? 1.0 : 0.0});
  }
  const TipHazard h = fit_tip_hazard(s);
  auto p = [&](double d, double lw) {
    return 1 / (1 + std::exp(-(h.alpha + h.beta * d + h.gamma * lw)));
  };
  CHECK(h.gamma < 0);
  for (double d : {0.0, 5.0, 11.0}) {
    CHECK(p(d, -2.3) > 0.9);
    CHECK(p(d, -1.7) < 0.1);
  }
  std::vector<TipSample> depth_only = s;
  for (TipSample& t : depth_only) t.log_width = 0;
  CHECK(h.log_likelihood > fit_tip_hazard(depth_only).log_likelihood + 100);
}

TEST_CASE("regrown extent: tip hazard takes the length when it explains the tips",
          "[skeleton_infer]") {
  // Axes that end in one long shoot (a conifer's twig, a weeping whip): tips exactly where
  // log l > 0.5, at every depth and width.
  Rng rng(6);
  std::vector<TipSample> s;
  for (int i = 0; i < 2000; ++i) {
    const double ll = -1 + 2 * rng.uniform01();
    s.push_back({double(rng.below(12)), -3 + rng.uniform01(), ll > 0.5 ? 1.0 : 0.0, ll});
  }
  const TipHazard h = fit_tip_hazard(s);
  auto p = [&](double d, double lw, double ll) {
    return 1 / (1 + std::exp(-(h.alpha + h.beta * d + h.gamma * lw + h.delta * ll)));
  };
  CHECK(h.delta > 0);
  for (double d : {0.0, 6.0, 11.0}) {
    CHECK(p(d, -2.5, 0.7) > 0.9);
    CHECK(p(d, -2.5, 0.3) < 0.1);
  }
  std::vector<TipSample> no_length = s;
  for (TipSample& t : no_length) t.log_length = 0;
  CHECK(h.log_likelihood > fit_tip_hazard(no_length).log_likelihood + 100);
}

TEST_CASE("regrown extent: conifer and weeping regrow narrower crowns than before",
          "[skeleton_infer]") {
  // Before the length term of the tip hazard and the gravitropism, the regrown crown was 1.55
  // (conifer) and 2.05 (weeping) times the input's; an axis that had jumped to a long twig
  // went on branching at that length. Now 1.37 and 1.63 (docs/skeleton-inference.md).
  struct Case {
    const char* path;
    double max_crown;
  };
  for (const Case& k :
       {Case{"examples/trees/conifer.ramus", 1.47}, Case{"examples/trees/weeping.ramus", 1.85}}) {
    const Skeleton tree = skeleton_test::grow_example(k.path, 1);
    GrammarOptions o;
    o.calibration_seeds = 4;
    const InferredGrammar g = infer_grammar(tree, o);
    Distributions a, b;
    for (int s = 1; s <= 4; ++s) measure(skeleton_test::grow_example(k.path, std::uint64_t(s)), a);
    for (int s = 1; s <= 8; ++s)
      measure(skeleton_test::grow_text("bundled_inferred.ramus", g.text, std::uint64_t(s)), b);
    const auto c = compare(a, b);
    INFO(k.path << " crown ratio " << ratio(of(c, Measure::CrownExtent)) << " length ratio "
                << ratio(of(c, Measure::TotalLength)));
    CHECK(ratio(of(c, Measure::CrownExtent)) < k.max_crown);
    CHECK(ratio(of(c, Measure::CrownExtent)) > 0.8);
    CHECK(ratio(of(c, Measure::TotalLength)) > 0.8);
    CHECK(ratio(of(c, Measure::TotalLength)) < 1.25);
  }
}

TEST_CASE("regrown extent: a tortuous skeleton regrows its crown, not a wider one",
          "[skeleton_infer]") {
  // A binary tree whose internodes zigzag (chord / path = cos 60 deg = 0.5): drawn straight with
  // their path length, the regrown crown was about twice as wide.
  Skeleton tree;
  Rng rng(11);
  struct Open {
    std::uint32_t node;
    Vec3 dir;
    double len;
    int level;
  };
  const std::uint32_t root = add_node(tree, {0, 0, 0}, kNoParent, 0.3);
  std::vector<Open> open{{root, {0, 0, 1}, 2.0, 0}};
  while (!open.empty()) {
    const Open o = open.back();
    open.pop_back();
    // Two half-segments kinked by +-60 degrees around the direction `dir`.
    const Vec3 side = normalized(cross(o.dir, Vec3{1, 0.3, 0}));
    const Vec3 p0 = tree.nodes[o.node].position;
    const Vec3 mid = p0 + o.dir * (0.5 * o.len * 0.5) + side * (0.5 * o.len * std::sin(kPi / 3));
    const Vec3 end = p0 + o.dir * (o.len * 0.5);
    const double r = tree.nodes[o.node].radius;
    const auto m = add_node(tree, mid, o.node, r * 0.9);
    const auto e = add_node(tree, end, m, r * 0.8);
    if (o.level == 5) continue;
    for (int k = 0; k < 2; ++k) {
      const double a = 2 * kPi * rng.uniform01();
      const Vec3 d =
          normalized(o.dir + Vec3{std::cos(a), std::sin(a), 0} * (0.6 + 0.2 * rng.uniform01()));
      open.push_back({e, d, o.len * 0.8, o.level + 1});
    }
  }
  GrammarOptions o;
  o.calibration_seeds = 4;
  const InferredGrammar g = infer_grammar(tree, o);
  CHECK(g.tortuosity == Approx(0.5).margin(0.02));
  const auto c = skeleton_test::regrow_and_compare(tree, g.text, "zigzag_inferred.ramus", 8);
  INFO(g.text);
  INFO("crown extent ratio " << ratio(of(c, Measure::CrownExtent)) << ", total length ratio "
                             << ratio(of(c, Measure::TotalLength)));
  CHECK(ratio(of(c, Measure::CrownExtent)) < 1.5);
  CHECK(ratio(of(c, Measure::CrownExtent)) > 0.6);
  CHECK(ratio(of(c, Measure::TotalLength)) > 0.6);
  CHECK(ratio(of(c, Measure::TotalLength)) < 1.6);
}

TEST_CASE("regrown extent: a real scan regrows its total length and crown extent",
          "[skeleton_infer]") {
  const std::string scan = std::string(RAMUS_SHARED_DIR) + "/data/adtree_tree1.xyz";
  const std::string out = skeleton_test::scratch("adtree_tree1_extent.ramus").string();
  auto r = cli_test::run_ramus(
      {"infer", scan, "-o", out, "--method", "skeleton", "--model", "clustered"});
  INFO(r.out);
  REQUIRE(r.status == 0);
  r = cli_test::run_ramus({"compare", scan, out, "--seeds", "10"});
  INFO(r.out);
  REQUIRE(r.status == 0);
  // "total length  1  10  mean(A)  mean(B)  KS" and the same for the crown extent.
  auto means = [&](const std::string& name, double& a, double& b) {
    const auto at = r.out.find(name);
    REQUIRE(at != std::string::npos);
    double ks = 0;
    unsigned na = 0, nb = 0;
    REQUIRE(std::sscanf(r.out.c_str() + at + name.size(), "%u %u %lf %lf %lf", &na, &nb, &a, &b,
                        &ks) == 5);
  };
  // Drawn straight and uncalibrated, the regrown crown was 3.5 times as wide. The bounds leave
  // room for changes in the reconstruction (measured: length 0.9-1.1, crown 1.3-2.34 over the
  // reconstructions of this scan so far, 64 to 201 internodes). The regrown length is
  // heavy-tailed over seeds: calibrated over 4 seeds, one reconstruction of this scan regrew
  // 2.27 x over 10 seeds and 1.89 x over 30; over the default 32, 0.73-1.22 x.
  double a = 0, b = 0;
  means("total length", a, b);
  CHECK(b / a > 0.5);
  CHECK(b / a < 2.0);
  means("crown extent", a, b);
  CHECK(b / a > 0.5);
  CHECK(b / a < 2.75);
}
