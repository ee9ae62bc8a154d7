// Tropism of an inferred grammar: the elasticity that explains how axes bend towards gravity.
//
// ABOP (Prusinkiewicz & Lindenmayer 1990) section 2.2, which the turtle implements (`tropism`,
// `elasticity`, docs/language.md): after each segment the heading H turns towards the tropism
// vector T by the angle alpha = e |H x T| about H x T. A grammar whose internodes are drawn
// with independent turns bends every axis by the same angle whatever its inclination, so a
// regrown branch curls on past the vertical where the input's hung and stopped; with tropism
// the bend fades as the axis nears T, as it does in the input (and in the bundled grammars).
//
// With T = (0, 0, -1) and beta(H) the angle between H and T, |H x T| = sin beta and the turn
// lowers beta by exactly alpha. Along an axis, a continuation internode's direction d after its
// parent's direction H therefore has beta(H) - beta(d) = n e sin beta(H) + noise, n the segments
// the grammar draws per internode; e is fitted by least squares on these pairs (closed form).
// The rules' angles are then measured from the bent heading, so that the written grammar
// (which bends after every F) does not count the bend twice.
#pragma once

#include <cstdint>
#include <vector>

#include "core/vec3.h"
#include "infer/skeleton/branch_rules.h"

namespace ramus::skeleton_infer {

// The least-squares elasticity of one set of continuation pairs.
struct ElasticityFit {
  double elasticity = 0;  // radians per drawn segment; > 0 bends towards T
  std::size_t pairs = 0;  // continuation pairs used
  double r2 = 0;          // share of the variance of beta(H) - beta(d) the fit explains
};

// Fits e over every continuation pair of `rules` (pooled over orders, `by_order` receives the
// fit of each order, indexed by order) with T = (0, 0, -1) and `segments` turns per internode.
// Pairs whose parent has an empty chord are left out. Orders with too few pairs (fewer than 3)
// have elasticity 0.
ElasticityFit fit_elasticity(const BranchRules& rules, int segments,
                             std::vector<ElasticityFit>* by_order = nullptr);

// H turned towards T by e |H x T| (ABOP 2.2), `segments` times: the turtle's heading after an
// internode drawn along H.
Vec3 bend_towards(Vec3 heading, const Vec3& tropism, double elasticity, int segments);

// Measures every child's theta and phi from its parent's bent heading (bend_towards of the
// parent's direction) instead of the direction itself, and reorders the laterals by the new
// azimuth. The continuation of each axis is kept.
void measure_from_bent_heading(BranchRules& rules, double elasticity, int segments);

}  // namespace ramus::skeleton_infer
