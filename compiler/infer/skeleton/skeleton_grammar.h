// Skeleton -> a small stochastic parametric L-system in the ramus language.
//
// Extraction (branch_rules.h, Eq. 4.11 of the thesis draft) gives one rule per internode; the
// clusters of rule_clustering.h generalize them. The grammar has one module N(l, w, o, i, d): an
// internode of length l and width w (twice the radius), branch order o, position i along its
// axis and depth d (internodes from the root). Per order group there is one stochastic
// production whose alternatives are the tip (the axis ends) and one branching alternative per
// cluster. Tips have the probability of a logistic function of depth (and of the log width,
// when the BIC prefers it) fitted to the order's internodes, its intercept optionally calibrated
// so that grown trees have the input's total length; the branching alternatives share the rest
// by their observed frequencies. Tortuous internodes are drawn as two kinked halves. Every
// angle and (log-)ratio is drawn from its cluster's fitted normal distribution, clamped to the
// observed range. Growth also stops at the longest observed axis of an order, past the deepest
// observed order, and after `derive` = the deepest observed internode. See
// docs/skeleton-inference.md.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "compiler/infer/skeleton/branch_rules.h"
#include "compiler/infer/skeleton/rule_clustering.h"
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
};

struct InferredGrammar {
  std::string text;  // canonical ramus source (what `ramus fmt` writes)
  std::vector<RuleGroup> groups;
  std::size_t productions = 0;   // productions of N, the fallback included
  std::size_t alternatives = 0;  // stochastic alternatives, the fallback counted as one
  std::size_t internodes = 0;
  std::size_t branch_nodes = 0;
  int derive = 0;
  double tip_shift = 0;   // added to every tip hazard's intercept by the calibration
  double tortuosity = 1;  // chord / path length of the internodes (length-weighted)
};

// Thrown when there is nothing to infer from (no segment at all).
struct InferError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Writes the grammar for the rules of `skeleton` (all its trees); the axiom starts like the
// tree with the most internode length. Throws ExtractError (invalid skeleton) or InferError.
InferredGrammar infer_grammar(const Skeleton& skeleton, const GrammarOptions& options);

// The same from rules already extracted.
InferredGrammar infer_grammar(const BranchRules& rules, const GrammarOptions& options);

// The probability that an internode is a tip, a logistic function of its depth d and the log of
// its width w:
//   p = 1 / (1 + exp(-(alpha + beta d + gamma log w))),
// fitted by (slightly ridge-penalized) maximum likelihood. Termination in the grammar: a tree
// grown by a width threshold (`A(l, w) : w > min -> ...`) has its tips where w falls, which depth
// alone only approximates.
struct TipHazard {
  double alpha = 0, beta = 0, gamma = 0;
  double log_likelihood = 0;  // of the fitted samples (for model selection)
};
struct TipSample {
  double depth = 0, log_width = 0;
  double tip = 0;  // 1 for a tip, else 0
};
TipHazard fit_tip_hazard(const std::vector<TipSample>& samples);
// Depth alone (gamma = 0).
TipHazard fit_tip_hazard(const std::vector<double>& depth, const std::vector<double>& is_tip);

// A number in the grammar: four significant digits, never an exponent form the reader would
// misread, "0" for zero.
std::string grammar_number(double v);

}  // namespace ramus::skeleton_infer
