// Skeleton -> a small stochastic parametric L-system in the ramus language.
//
// Extraction (branch_rules.h, Eq. 4.11 of the thesis draft) gives one rule per internode; the
// clusters of rule_clustering.h generalize them. The grammar has one module N(l, w, o, i, d, r):
// an internode of length l and width w (twice the radius), branch order o, position i along its
// axis, depth d (internodes from the root) and r the length left to its axis. Per order group
// there is a stochastic production with one branching alternative per cluster, by their
// observed frequencies, guarded by the axis budget r (AxisBudget below: every lateral draws its
// axis's length where it starts), and the fallback tip ends the axis; how the budget ends an
// axis is GrammarOptions::AxisEnds (own tips and last branch nodes, or one length model for
// every internode, chosen per input). The finest laterals' budgets are optionally calibrated so
// that grown trees have the input's total length. Without axis budgets (the module has no r),
// each production has a tip alternative instead, of the probability of a logistic function of
// depth (and of the log width and log length, when the BIC prefers them) fitted to the order's
// internodes, its intercept calibrated. Tortuous internodes are drawn as
// two kinked halves; a fitted gravitropism (tropism_fit.h) is written as `tropism` and
// `elasticity`. Every angle and (log-)ratio is drawn from its cluster's fitted normal
// distribution, clamped to the observed range. Growth also stops at the longest observed axis
// of an order, past the deepest observed order, and after `derive` = the deepest observed
// internode. See docs/skeleton-inference.md.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "compiler/infer/skeleton/branch_rules.h"
#include "compiler/infer/skeleton/rule_clustering.h"
#include "compiler/infer/skeleton/tropism_fit.h"
#include "core/skeleton.h"

namespace ramus::skeleton_infer {

struct GrammarOptions {
  ClusterOptions cluster;
  int max_rules = 32;       // alternatives over all productions, the fallback included
  std::string source_name;  // named in the header comment
  std::string system_name = "inferred";
  // Calibrate the tip hazards against the input's total length over this many grown seeds
  // (0: no calibration). See calibrate_tip_shift in the .cpp.
  int calibration_seeds = 0;
  // Fit the elasticity of a gravitropism (tropism_fit.h) and write it into the grammar; the
  // rules' angles are then measured from the bent heading.
  bool tropism = true;
  // End every axis when its length budget is spent (AxisBudget below) instead of by the tip
  // hazard of every internode.
  bool axis_budget = true;
  // How the axes end under budgets. `own`: a tip takes what is left of its budget, the last
  // branch nodes of the axes are a production of their own, single-internode laterals a budget
  // of their own (LateralBudget), the drawn lengths those of the internodes that branch again;
  // guards halfway between the budgets they tell apart (see the .cpp). `shared`: every
  // internode, the tips included, is drawn from one length model, and an axis ends when its
  // budget holds less than this internode and half of a next one. `automatic`: both are
  // written and calibrated, trees are grown from each over calibration_seeds seeds, and the one
  // closer to the input (select_axis_ends) is kept -- only infer_grammar(Skeleton) can measure
  // that; from rules alone, and without calibration, automatic means own.
  enum class AxisEnds { automatic, own, shared };
  AxisEnds axis_ends = AxisEnds::automatic;
};

struct InferredGrammar {
  std::string text;  // canonical ramus source (what `ramus fmt` writes)
  std::vector<RuleGroup> groups;
  std::size_t productions = 0;   // productions of N, the fallback included
  std::size_t alternatives = 0;  // stochastic alternatives, the fallback counted as one
  std::size_t internodes = 0;
  std::size_t branch_nodes = 0;
  int derive = 0;
  // Found by the calibration: added to every tip hazard's intercept, or with axis budgets to
  // every lateral axis's log budget.
  double tip_shift = 0;
  double tortuosity = 1;  // chord / path length of the internodes (length-weighted)
  // The fitted tropism: `elasticity` (radians per F, > 0 towards the ground) pooled over the
  // orders, as written; the fit of each order, for the header comment and the CLI's report.
  ElasticityFit tropism;
  std::vector<ElasticityFit> tropism_by_order;
  // The model written (own or shared) and, after an automatic choice, the distance of each
  // candidate's grown trees to the input (GrownDistance; negative when not measured).
  GrammarOptions::AxisEnds axis_ends = GrammarOptions::AxisEnds::own;
  double distance_own = -1, distance_shared = -1;
};

// Thrown when there is nothing to infer from (no segment at all).
struct InferError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Writes the grammar for the rules of `skeleton` (all its trees); the axiom starts like the
// tree with the most internode length. Throws ExtractError (invalid skeleton) or InferError.
// With AxisEnds::automatic it writes both models and keeps the one of smaller grown_distance.
InferredGrammar infer_grammar(const Skeleton& skeleton, const GrammarOptions& options);

// The same from rules already extracted.
InferredGrammar infer_grammar(const BranchRules& rules, const GrammarOptions& options);

// How far the trees grown from `text` with seeds 1..`seeds` are from `skeleton`: the sum of the
// Kolmogorov-Smirnov distances of branch length, branching angle and branch order (fidelity.h)
// and of |ln(grown / input)| of the mean total length, crown extent and height. Infinite when
// a growth exceeds the module limit of the calibration.
double grown_distance(const std::string& text, const Skeleton& skeleton, int seeds);

// The probability that an internode is a tip, a logistic function of its depth d, the log of
// its width w and the log of its length l:
//   p = 1 / (1 + exp(-(alpha + beta d + gamma log w + delta log l))),
// fitted by (slightly ridge-penalized) maximum likelihood. Termination in the grammar: a tree
// grown by a width threshold (`A(l, w) : w > min -> ...`) has its tips where w falls, which depth
// alone only approximates; a tree whose axes end in a long shoot (a conifer's twig, a weeping
// tree's whip) has its tips where l jumps. A feature that is constant over the samples (0 when
// not wanted) is left out.
struct TipHazard {
  double alpha = 0, beta = 0, gamma = 0, delta = 0;
  double log_likelihood = 0;  // of the fitted samples (for model selection)
};
struct TipSample {
  double depth = 0, log_width = 0;
  double tip = 0;         // 1 for a tip, else 0
  double log_length = 0;  // last, so that {depth, log width, tip} still initializes a sample
};
TipHazard fit_tip_hazard(const std::vector<TipSample>& samples);
// Depth alone (gamma = 0).
TipHazard fit_tip_hazard(const std::vector<double>& depth, const std::vector<double>& is_tip);

// The length of a lateral axis (its first internode and all that continue it), log-normal with
// a mean linear in the carrying internode's log length, log width and depth:
//   log L = c0 + cl log l + cw log w + cd d + normal(0, sd), clamped to [lo, hi],
// fitted by least squares, the terms chosen by the BIC. The grammar draws it where the lateral
// starts and passes the rest down the axis; an internode continues its axis only while more
// than half an internode of the budget is left after it. A per-internode tip decision cannot
// tell an axis that jumps to a long shoot and then stops from one that keeps branching out
// there, and the regrown crowns were 1.4 to 2.6 times as wide as the input; the budget ties the
// reach of every axis to what the input's axes of its kind reach.
struct AxisBudget {
  double c0 = 0, cl = 0, cw = 0, cd = 0, sd = 0, lo = 0, hi = 0;
  std::size_t samples = 0;
};
struct BudgetSample {
  double log_length = 0, log_width = 0, depth = 0;  // of the internode carrying the lateral
  double log_axis = 0;                              // log of the lateral axis's length
  bool single = false;  // the axis is one internode, a tip (a whip, a twig, a spur)
};
AxisBudget fit_axis_budget(const std::vector<BudgetSample>& samples);

// Laterals are of two kinds: axes of one internode (a tip: a weeping tree's whip, a spur) and
// axes that branch. Their lengths differ (a whip 3.6 m, a scaffold limb of 5 to 8 m) and so does
// what a budget does with them (a single internode's length is its budget; a branching axis
// spends its budget over internodes), so they are fitted apart: with probability p_single a
// lateral draws the budget of the single ones, else that of the branching ones. One kind alone
// gives p_single 0 or 1.
struct LateralBudget {
  AxisBudget branching, single;
  double p_single = 0;
};
LateralBudget fit_lateral_budget(const std::vector<BudgetSample>& samples);

// A number in the grammar: four significant digits, never an exponent form the reader would
// misread, "0" for zero.
std::string grammar_number(double v);

}  // namespace ramus::skeleton_infer
