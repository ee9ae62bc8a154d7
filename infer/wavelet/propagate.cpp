// Axiom perturbation for geometry propagation (see propagate.h). Reference: S. Friedman and
// I. Stamos, "Automatic Procedural Modeling of Tree Structures in Point Clouds Using Wavelets",
// 3DV 2013, Sections III-G and IV-C.
#include "infer/wavelet/propagate.h"

#include <cmath>
#include <stdexcept>

#include "compiler/derive.h"
#include "core/rng.h"

namespace ramus::wavelet {
namespace {

// Stream keys, so the seed and the argument draws of one tree never share a stream.
constexpr std::uint64_t kSeedKey = 0x70726f70u;  // "prop"
constexpr std::uint64_t kArgKey = 0x61786d73u;   // "axms"

// Appends a constant expression holding `value` and returns its code id. Every axiom argument
// gets its own code, so codes shared with productions (lowering may reuse them) stay unchanged.
ir::CodeId add_constant_code(ir::Grammar& g, double value, std::uint32_t where) {
  ir::Code c;
  c.begin = std::uint32_t(g.code.size());
  g.code.push_back({ir::Op::Const, std::uint32_t(g.consts.size())});
  g.consts.push_back(value);
  c.end = c.begin + 1;
  c.max_stack = 1;
  c.shape = ir::Code::Shape::Constant;
  c.value = value;
  c.where = where;
  g.codes.push_back(c);
  return ir::CodeId(g.codes.size() - 1);
}

}  // namespace

std::uint64_t propagated_seed(std::uint64_t seed, std::uint64_t k) {
  return Rng::stream(seed, kSeedKey, k).next_u64();
}

PropagatedGrammar propagate_grammar(const ir::Grammar& g, std::uint64_t k,
                                    const PropagateOptions& options) {
  if (!std::isfinite(options.jitter) || options.jitter < 0 || options.jitter >= 1) {
    throw std::invalid_argument("the jitter must be in [0, 1)");
  }
  PropagatedGrammar out;
  out.grammar = g;
  ir::Grammar& pg = out.grammar;
  out.seed = propagated_seed(options.seed, k);
  pg.settings.seed = out.seed;

  // The axiom's arguments are constant expressions: evaluate them once (with the original
  // grammar, whose seed they cannot depend on: random draws are not allowed in an axiom).
  const ModuleString axiom = axiom_string(g);
  Rng rng = Rng::stream(options.seed, kArgKey, k);
  for (std::size_t m = 0; m < pg.axiom.size(); ++m) {
    ir::SuccModule& mod = pg.axiom[m];
    if (mod.nargs == 0) continue;
    const std::uint32_t begin = std::uint32_t(pg.args.size());
    for (std::uint32_t a = 0; a < mod.nargs; ++a) {
      const double v = axiom.param(m, a);
      // One draw per argument whether or not it changes, so argument i's factor does not depend
      // on the values of the arguments before it.
      const double factor = 1.0 + options.jitter * rng.uniform(-1.0, 1.0);
      const double w = v * factor;
      out.perturbed_args += w != v;
      const std::uint32_t where = g.codes[g.args[mod.arg_begin + a]].where;
      pg.args.push_back(add_constant_code(pg, w, where));
    }
    mod.arg_begin = begin;
  }
  return out;
}

}  // namespace ramus::wavelet
