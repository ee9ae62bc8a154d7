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

#include "core/skeleton.h"
#include "infer/skeleton/branch_rules.h"
#include "infer/skeleton/budget_fits.h"
#include "infer/skeleton/infer_error.h"
#include "infer/skeleton/production_text.h"
#include "infer/skeleton/rule_clustering.h"
#include "infer/skeleton/tropism_fit.h"

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

}  // namespace ramus::skeleton_infer
