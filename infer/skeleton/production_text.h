// The pieces of text an inferred skeleton grammar is written from: random draws of fitted
// distributions, the turtle turns and internodes of one child, a production's alternative, the
// axis budget draws and the guards that end axes. Every number goes through grammar_number.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "infer/skeleton/budget_fits.h"
#include "infer/skeleton/rule_clustering.h"

namespace ramus::skeleton_infer {

// A number in the grammar: four significant digits, never an exponent form the reader would
// misread, "0" for zero.
std::string grammar_number(double v);

// What `ramus fmt` writes for an inferred grammar's text. Throws InferError when it does not
// parse (an internal error: inference writes it).
std::string canonical_layout(const std::string& text);

// The observed range of internode lengths: a child's length is kept inside it, so that the
// product of many ratios cannot run away from what the tree shows.
struct LengthRange {
  double min = 0, max = 0;
};

// Below this kink (degrees) an internode is drawn straight (see segment).
constexpr double kMinKink = 10;

// `clamp(normal(m, s), lo, hi)`, or the mean alone when the spread is nil.
std::string draw(const Fitted& f);
// A log-normal ratio of the parent's value `parent` (a parameter name).
std::string draw_ratio(const Fitted& f, const char* parent);
std::string draw_angle(const FittedAngle& f);
// The turtle turns of one child: level the frame, roll by phi, pitch down by theta.
std::string turn(const ChildDistribution& c);
// An internode of length `len`, kinked by +-kink_degrees when the input's internodes bend.
std::string segment(double kink_degrees, const std::string& len, bool random_roll = true);
// One child module N(...) with its turns; `rest` are its parameters after length and width.
std::string child(const ChildDistribution& d, const LengthRange& range, const std::string& rest);
// One alternative of a production: the internode, its lateral children, its continuation.
std::string alternative(const RuleCluster& c, const LengthRange& range, double kink,
                        const std::string& lateral_budget, const LengthRange* tips = nullptr);
// The draw of a lateral axis's length budget, its log moved by `shift`.
std::string budget_draw(const AxisBudget& b, double shift);
std::string budget_draw(const LateralBudget& b, double shift);
// The guards that tell where an axis ends (see production_text.cpp).
std::string carries_guard(double tip);
std::string branching_guard(double next, double tip);
std::string continue_guard(double next);
// Observed frequencies as decimals with six places that sum to exactly 1.
std::vector<std::string> probabilities(const std::vector<std::size_t>& counts);

}  // namespace ramus::skeleton_infer
