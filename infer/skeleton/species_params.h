// The species-level quantities of an inferred grammar: what a person would change to get another
// tree of the same kind (a wider branch angle, longer laterals, more drooping shoots). They are
// measured on the shoots that hang from the scaffold (scaffold.h) -- the finer internodes the
// grammar grows by its rules -- and written as the grammar's `param` block, used by name in its
// productions, so `-D branch_angle=70` does what it says.
//
// Every quantity is a median or a mean of the internodes it is about, robust to the few odd ones
// a reconstruction makes; chord lengths (straight start-to-end distances) rather than path
// lengths, because the rules draw every internode straight.
#pragma once

#include <cstddef>

#include "infer/skeleton/branch_rules.h"
#include "infer/skeleton/scaffold.h"

namespace ramus::skeleton_infer {

struct SpeciesParams {
  double branch_angle = 45, branch_angle_sd = 10;  // degrees between a lateral and its parent
  double kink_angle = 10, kink_angle_sd = 5;  // degrees between successive internodes of an axis
  // Where around its parent a lateral, and a shoot's next internode, turn: the angle of the turn
  // from straight up in the parent's levelled frame (branch_rules.h: |phi - 180|), 0 up, 90 to
  // the side, 180 down. Successive internodes turn to alternate sides.
  double lateral_side = 90, lateral_side_sd = 30;
  double kink_side = 90, kink_side_sd = 30;
  double internode_length = 0, internode_length_sd = 0;  // chord of a shoot's internodes
  double continuation_width = 0.9;                       // width of the next internode / this one
  double lateral_width = 0.6;                            // width of a lateral / its parent
  double lateral_share = 0.3;  // of the length a shoot carries past an internode, a lateral's share
  double p_one = 0.5, p_two = 0.1;  // internodes that go on with one, with two or more laterals
  double min_internode = 0, max_internode = 0;  // internode chords kept in this range
  double elasticity = 0;                        // gravitropism (ABOP 2.2), fitted by tropism_fit.h
  int depth = 1;  // derivation steps: the deepest chain of internodes of a shoot
};

// `rules` are measured from the bent heading when a tropism is written (tropism_fit.h); `height`
// bounds the internode lengths (no internode over a fifth of it).
SpeciesParams fit_species_params(const BranchRules& rules, const Scaffold& scaffold, double height);

}  // namespace ramus::skeleton_infer
