// The termination models of an inferred skeleton grammar and their fits: where axes end (the
// tip hazard) and how long lateral axes are (the axis length budgets).
#pragma once

#include <cstddef>
#include <vector>

namespace ramus::skeleton_infer {

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

}  // namespace ramus::skeleton_infer
