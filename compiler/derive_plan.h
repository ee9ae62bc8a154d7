// What a derivation pass precomputes from the grammar before its sweeps (compiler/derive.cpp,
// docs/engine.md "Derivation"): per symbol, whether the symbol alone decides a module's
// production (SymbolPlan), and per alternative its successor flattened for the write sweep,
// with arguments written twice evaluated once (Successors). Internal to derive.cpp.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "compiler/ir.h"
#include "core/rng.h"

namespace ramus::derive_plan {

// What a pass knows about a module from its symbol alone. Copy: no production has it as
// predecessor. Fixed: its first production has no context, no guard and one deterministic
// alternative, so every module with the predecessor's parameter count takes that alternative
// -- the sweeps then neither match, nor store a choice, nor draw. Weighted: the first
// production has no context and no guard and its alternatives constant probabilities, so a
// module draws its alternative without matching or evaluating anything. Anything else (and a
// module whose parameter count is not the predecessor's) is chosen by matching productions.
struct SymbolPlan {
  enum Kind : std::uint8_t { Copy, Fixed, Weighted, General };
  static constexpr std::uint16_t kAnyParams = 0xffff;
  Kind kind = Copy;
  std::uint16_t nparams = 0;   // Fixed, Weighted: the predecessor's parameter count, or kAnyParams
  std::uint32_t alt = 0;       // Fixed: the alternative; Weighted: the first alternative
  std::uint32_t mods = 0;      // Fixed: modules and parameters it writes
  std::uint32_t params = 0;    // Weighted: the number of alternatives
  std::uint32_t weights = 0;   // Weighted: first of them in Pass::weights, then their sum
  std::uint32_t fallback = 0;  // Weighted: the last alternative with a positive weight

  bool takes(std::uint32_t np) const { return nparams == kAnyParams || nparams == np; }
  bool fixed_for(std::uint32_t np) const { return kind == Fixed && takes(np); }
};

// The probabilities of a production when all are constants, not negative and not all zero
// (else the general path evaluates them and reports the error).
inline bool constant_weights(const ir::Grammar& g, const ir::Production& p,
                             std::vector<double>& w) {
  const std::uint32_t n = p.alt_end - p.alt_begin;
  if (n < 1 || n > 64) return false;
  const std::size_t first = w.size();
  double sum = 0;
  for (std::uint32_t k = 0; k < n; ++k) {
    const ir::CodeId c = g.alternatives[p.alt_begin + k].probability;
    const double v = c == ir::kNoCode ? 1.0 : g.codes[c].value;
    if ((c != ir::kNoCode && g.codes[c].shape != ir::Code::Shape::Constant) || v < 0) {
      w.resize(first);
      return false;
    }
    w.push_back(v);
    sum += v;
  }
  if (!(sum > 0)) {
    w.resize(first);
    return false;
  }
  w.push_back(sum);
  return true;
}

// The last alternative with a positive weight (pick_weighted's fallback).
inline std::uint32_t last_positive(const double* w, std::uint32_t n) {
  for (std::uint32_t k = n; k-- > 0;) {
    if (w[k] > 0) return k;
  }
  return 0;
}

inline std::vector<SymbolPlan> plan_symbols(const ir::Grammar& g, const ir::Table& table,
                                            std::vector<double>& weights) {
  std::vector<SymbolPlan> plans(g.symbols.size());
  const bool nearest = g.selection == ir::Selection::Nearest && &table == &g.rewrite;
  for (std::size_t s = 0; s < plans.size() && s + 1 < table.first.size(); ++s) {
    const std::uint32_t b = table.first[s], e = table.first[s + 1];
    if (b == e) continue;
    SymbolPlan& plan = plans[s];
    plan.kind = SymbolPlan::General;
    const ir::Production& p = g.productions[table.index[b]];
    if (nearest || p.has_context() || p.guard != ir::kNoCode) continue;
    plan.nparams = p.predecessor.any_params ? SymbolPlan::kAnyParams : p.predecessor.nparams;
    plan.alt = p.alt_begin;
    if (p.alt_end - p.alt_begin == 1 && g.alternatives[p.alt_begin].probability == ir::kNoCode) {
      const ir::Alternative& alt = g.alternatives[p.alt_begin];
      plan.kind = SymbolPlan::Fixed;
      plan.mods = alt.succ_end - alt.succ_begin;
      plan.params = alt.out_params;
    } else if (const auto first = std::uint32_t(weights.size()); constant_weights(g, p, weights)) {
      plan.kind = SymbolPlan::Weighted;
      plan.params = p.alt_end - p.alt_begin;
      plan.weights = first;
      plan.fallback = last_positive(weights.data() + first, plan.params);
    }
  }
  return plans;
}

// Pass::pick() for constant weights w[0..n) with their sum w[n], drawing the same number and
// taking the same alternative: the first k with u < w[k], u decreased by each weight passed
// (the same subtractions), else `fallback`, the last positive weight (rounding left u at the
// top end). Written without a branch on u: the draw is random, so a branch on it would be
// mispredicted about every other module.
inline std::uint32_t pick_weighted(const double* w, std::uint32_t n, std::uint32_t fallback,
                                   Rng rng) {
  double u = rng.uniform01() * w[n];
  std::uint64_t below = 0;  // bit j: u < w[j] after the weights before j were subtracted
  for (std::uint32_t j = 0; j < n; ++j) {
    below |= std::uint64_t(u < w[j]) << j;
    u -= w[j];
  }
  const auto k = std::uint32_t(std::countr_zero(below));  // 64 when no bit is set
  return k < n ? k : fallback;
}

// Whether codes a and b always give the same value for the same slots: the same pure
// expression written twice (`[+A(s/r)][-A(s/r)]`), so a successor evaluates it once.
inline bool same_pure_code(const ir::Grammar& g, ir::CodeId a, ir::CodeId b) {
  const ir::Code &x = g.codes[a], &y = g.codes[b];
  if (x.random || y.random || x.shape != y.shape) return false;
  switch (x.shape) {
    case ir::Code::Shape::Constant:
      return x.value == y.value && std::signbit(x.value) == std::signbit(y.value);
    case ir::Code::Shape::Param:
      return x.slot == y.slot;
    case ir::Code::Shape::ParamOpConst:
      return x.slot == y.slot && x.op == y.op && x.value == y.value &&
             std::signbit(x.value) == std::signbit(y.value);
    case ir::Code::Shape::General:
      break;
  }
  if (x.end - x.begin != y.end - y.begin) return false;
  for (std::uint32_t k = 0; k < x.end - x.begin; ++k) {
    const ir::Instr &i = g.code[x.begin + k], &j = g.code[y.begin + k];
    if (i.op != j.op) return false;
    if (i.op == ir::Op::Const ? g.consts[i.a] != g.consts[j.a] ||
                                    std::signbit(g.consts[i.a]) != std::signbit(g.consts[j.a])
                              : i.a != j.a) {
      return false;
    }
  }
  return true;
}

// An alternative's successor flattened for the write sweep: its symbols, their argument
// counts and one ArgOp per argument, in the order they are written.
struct ArgOp {
  enum Kind : std::uint8_t { Same, Constant, Param, ParamOpConst, General };
  Kind kind = General;
  ir::Op op = ir::Op::Add;
  std::uint16_t same = 0;  // Same: an earlier argument of the alternative with the same pure code
  std::uint32_t slot = 0;
  double value = 0;
  ir::CodeId code = 0;
};
// The write sweep writes a successor's symbols and offsets in one loop and its arguments in
// another, without a loop per module over its arguments.
struct Successors {
  std::vector<std::uint32_t> first_module, first_arg;  // per alternative
  std::vector<ir::SymbolId> symbols;
  std::vector<std::uint32_t> offsets;  // per module: the successor's arguments before it
  std::vector<ArgOp> args;

  explicit Successors(const ir::Grammar& g) {
    for (const ir::Alternative& alt : g.alternatives) {
      first_module.push_back(std::uint32_t(symbols.size()));
      const auto first = std::uint32_t(args.size());
      first_arg.push_back(first);
      for (std::uint32_t m = alt.succ_begin; m < alt.succ_end; ++m) {
        const ir::SuccModule& sm = g.successors[m];
        symbols.push_back(sm.symbol);
        offsets.push_back(std::uint32_t(args.size()) - first);
        for (std::uint32_t k = 0; k < sm.nargs; ++k) args.push_back(op(g, sm.arg_begin + k, first));
      }
    }
  }

  ArgOp op(const ir::Grammar& g, std::uint32_t arg, std::uint32_t first) const {
    ArgOp a;
    a.code = g.args[arg];
    // The last 64 arguments at most: planning stays linear in a long successor.
    const std::size_t from = std::max<std::size_t>(first, args.size() > 64 ? args.size() - 64 : 0);
    for (std::size_t j = from; j < args.size(); ++j) {
      if (j - first <= 0xffff && same_pure_code(g, args[j].code, a.code)) {
        a.kind = ArgOp::Same;
        a.same = std::uint16_t(j - first);
        return a;
      }
    }
    const ir::Code& c = g.codes[a.code];
    a.op = c.op;
    a.slot = c.slot;
    a.value = c.value;
    switch (c.shape) {
      case ir::Code::Shape::Constant:
        a.kind = ArgOp::Constant;
        break;
      case ir::Code::Shape::Param:
        a.kind = ArgOp::Param;
        break;
      case ir::Code::Shape::ParamOpConst:
        a.kind = ArgOp::ParamOpConst;
        break;
      case ir::Code::Shape::General:
        break;
    }
    return a;
  }
};

// Everything a pass plans from the grammar alone: the flattened successors, per alternative + 1
// the modules and parameters it writes (0: a copied module, one module of its own parameters),
// and per table its symbol plans. derive() plans once for all its passes, since a pass over a
// short string would spend a good part of its time planning (a microsecond a pass).
struct PassPlan {
  struct Table {
    bool planned = false;
    std::vector<SymbolPlan> plans;
    std::vector<double> weights;         // SymbolPlan::Weighted
    std::vector<std::uint8_t> rewrites;  // per symbol: 1 unless its plan is Copy
  };
  const ir::Grammar* grammar;
  Successors succ;
  std::vector<std::uint32_t> out_mods{1}, out_params{0};
  Table tables[3];  // per ir::Kind

  explicit PassPlan(const ir::Grammar& g) : grammar(&g), succ(g) {
    for (const ir::Alternative& alt : g.alternatives) {
      out_mods.push_back(alt.succ_end - alt.succ_begin);
      out_params.push_back(alt.out_params);
    }
  }
  // The plans of table `kind`, made on first use.
  const Table& table(ir::Kind kind) {
    Table& t = tables[std::size_t(kind)];
    if (!t.planned) {
      t.plans = plan_symbols(*grammar, grammar->table(kind), t.weights);
      for (const SymbolPlan& plan : t.plans) t.rewrites.push_back(plan.kind != SymbolPlan::Copy);
      t.planned = true;
    }
    return t;
  }
};

}  // namespace ramus::derive_plan
