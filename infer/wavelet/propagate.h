// Geometry propagation (Friedman & Stamos 2013, IV-C): many similar yet distinct trees from one
// grammar. "To ensure variety random perturbations can be applied to the starting axiom so that a
// different set of productions will be chosen" (IV-C; III-G: "the dyad from the input should
// first be perturbed"). Tree k of a propagation gets
//   - its own derivation seed, mixed from (seed, k), so stochastic productions choose anew, and
//   - an axiom whose numeric arguments are each multiplied by 1 + jitter * u, u uniform in
//     [-1, 1) drawn from Rng::stream(seed, k, argument index): lengths, angles and widths of the
//     axiom's vectors move by up to +-jitter of their size, so nearest-rule selection (III-G)
//     and guards pick other productions. Zero arguments stay zero.
// Everything else in the grammar is kept. The result depends only on (grammar, seed, k, jitter).
#pragma once

#include <cstddef>
#include <cstdint>

#include "compiler/ir.h"

namespace ramus::wavelet {

struct PropagateOptions {
  std::uint64_t seed = 1;
  double jitter = 0.1;  // relative amplitude of the axiom perturbation, in [0, 1)
};

struct PropagatedGrammar {
  ir::Grammar grammar;
  std::uint64_t seed = 0;          // the derivation seed of this tree (grammar.settings.seed)
  std::size_t perturbed_args = 0;  // axiom arguments that changed
};

// The derivation seed of tree `k`.
std::uint64_t propagated_seed(std::uint64_t seed, std::uint64_t k);

// Tree `k` of the propagation of `g`. Throws std::invalid_argument for a jitter outside [0, 1)
// or not finite.
PropagatedGrammar propagate_grammar(const ir::Grammar& g, std::uint64_t k,
                                    const PropagateOptions& options);

}  // namespace ramus::wavelet
