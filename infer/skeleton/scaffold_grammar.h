// Skeleton -> grammar that regrows this tree: the scaffold (trunk and main limbs, scaffold.h) as
// the axiom, drawn as measured, and the finer shoots that hang from it as buds A(l, w, r) grown
// by three stochastic productions whose numbers are the named species-level params of
// species_params.h (docs/skeleton-inference.md, "Scaffold grammars").
//
// Why: a grammar of per-internode statistics alone (skeleton_grammar.h, `--model clustered`)
// matches each distribution and still grows another tree: a kinked or tilted trunk, a few giant
// straight limbs, 0.6-0.9 of the height, an envelope overlap of 0.16-0.31 with the scan. Here the
// height, lean, crown outline and limb placement are the input's; each bud keeps the measured
// reach of the shoot it stands for, so the outline of the fine growth is the input's too, and
// seeds vary only the fine detail: grown with another seed the tree is a sibling.
//
// The axiom follows the turtle (compiler/turtle_frame.h) while it is written: each turn is
// computed from the frame the turtle will really have there, after the rounding of the written
// numbers and the tropism bend of every F, so the drawn scaffold does not drift.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/skeleton.h"
#include "infer/skeleton/scaffold.h"
#include "infer/skeleton/species_params.h"
#include "infer/skeleton/tropism_fit.h"

namespace ramus::skeleton_infer {

struct ScaffoldGrammarOptions {
  ScaffoldOptions scaffold;
  bool tropism = true;  // fit and write a gravitropism (tropism_fit.h)
  std::uint64_t seed = 1;
  std::string system_name = "inferred";
  std::string source_name;  // named in the header comment
};

struct ScaffoldGrammar {
  std::string text;  // canonical layout (`ramus fmt`)
  SpeciesParams params;
  ElasticityFit tropism;
  std::size_t scaffold_axes = 0, scaffold_segments = 0, buds = 0;
  std::size_t productions = 0;
  int steps = 0;               // the grammar's derive
  std::size_t internodes = 0;  // of the input's tree
  double height = 0;           // of the input's tree
};

// Throws ExtractError (an invalid skeleton) or InferError (no segment, or a tree with no height
// and no extent to draw).
ScaffoldGrammar infer_scaffold_grammar(const Skeleton& skeleton,
                                       const ScaffoldGrammarOptions& options = {});

}  // namespace ramus::skeleton_infer
