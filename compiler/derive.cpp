#include "compiler/derive.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <new>
#include <thread>

#include "compiler/bracket_balance.h"
#include "compiler/context.h"
#include "compiler/derive_plan.h"
#include "compiler/expr_vm.h"
#include "compiler/parallel_chunks.h"

namespace ramus {

namespace {

using derive_plan::ArgOp;
using derive_plan::pick_weighted;
using derive_plan::Successors;
using derive_plan::SymbolPlan;

constexpr std::size_t kChunk = 1 << 15;  // modules per chunk: fixed, so output ignores threads

// A decoded .rmb may hold location indexes the verifier did not tie to the table (found by
// fuzz_decode_rmb): an index out of range reads as "?" instead of past the end.
const std::string& location_of(const ir::Grammar& g, std::size_t where) {
  static const std::string unknown = "?";
  return where < g.locations.size() ? g.locations[where] : unknown;
}

std::string describe(const ir::Grammar& g, const ir::Production& p, const ExprError& e,
                     const PassInfo& info, std::size_t i) {
  const std::string& at = e.code < g.codes.size() ? location_of(g, g.codes[e.code].where)
                                                  : location_of(g, std::size_t(-1));
  return at + ": " + e.what() + " in production `" + p.text + "` (" + location_of(g, p.where) +
         ") at " + info.where + ", module " + std::to_string(i);
}

// A module holds at most kMaxModuleParams parameters (compiler/module_string.h): a successor
// with more is refused before it is written (lowering refuses it too; an .rmb may hold one).
void check_successor_arity(const ir::Grammar& g) {
  for (const ir::Alternative& alt : g.alternatives) {
    for (std::uint32_t m = alt.succ_begin; m < alt.succ_end; ++m) {
      if (g.successors[m].nargs <= kMaxModuleParams) continue;
      const ir::Production& p = g.productions[alt.production];
      throw DeriveError(location_of(g, p.where) + ": production `" + p.text +
                        "` writes a module with " + std::to_string(g.successors[m].nargs) +
                        " parameters; a module holds at most " + std::to_string(kMaxModuleParams));
    }
  }
}

// Everything a sweep reads; one per pass, shared read-only by the chunks.
struct Pass {
  const ir::Grammar& g;
  const ir::Table& table;
  const ModuleString& in;
  const ContextTables* ctx;
  const PassInfo& info;
  std::uint64_t stream;  // stream_prefix(seed, key): each module's streams from it
  // What the pass planned from the grammar (derive_plan::PassPlan).
  const std::vector<SymbolPlan>& plans;
  const std::vector<double>& weights;  // SymbolPlan::Weighted
  const Successors& succ;
  // Per alternative + 1 (0: a copied module), the modules and parameters it writes (a copy
  // writes its own parameter count instead of out_params[0]).
  const std::vector<std::uint32_t>& out_mods;
  const std::vector<std::uint32_t>& out_params;
  const std::vector<std::uint8_t>& rewrites;  // per symbol: 1 unless its plan is Copy
  // Per chunk, for each module its symbol does not decide (in order): 0 copy, else
  // alternative + 1.
  std::vector<PodVector<std::uint32_t>>* choices = nullptr;

  // Binds production p's slots for module i and checks its predecessor and contexts.
  bool match(const ir::Production& p, std::size_t i, double* slots) const {
    if (p.has_context()) return match_production(g, p, in, ctx, i, slots);
    const ir::Pattern& pat = p.predecessor;
    if (in.symbol(i) != pat.symbol) return false;
    if (pat.any_params) return true;
    if (in.nparams(i) != pat.nparams) return false;
    const double* x = in.params(i);
    for (std::uint32_t k = 0; k < pat.nparams; ++k) slots[pat.first_slot + k] = x[k];
    return true;
  }

  // Picks the alternative for module i (0: copied) by matching. Guards and probabilities draw
  // from the module's matching stream (seed, key, 2i). Out of line: the choose sweep's loop
  // keeps its counters in registers.
  [[gnu::noinline]] std::uint32_t choose(std::size_t i) const {
    double slots[ir::kMaxSlots];
    const ir::SymbolId s = in.symbol(i);
    const std::uint32_t b = table.first[s], e = table.first[s + 1];
    if (b == e) return 0;
    LazyRng rng(stream, 2 * std::uint64_t(i));
    if (g.selection == ir::Selection::Nearest && &table == &g.rewrite) {
      return choose_nearest(i, b, e, slots, rng);
    }
    for (std::uint32_t k = b; k < e; ++k) {
      const ir::Production& p = g.productions[table.index[k]];
      if (!match(p, i, slots)) continue;
      try {
        if (p.guard != ir::kNoCode && eval(g, p.guard, slots, rng) == 0) continue;
        return alternative(p, slots, rng);
      } catch (const ExprError& err) {
        throw DeriveError(describe(g, p, err, info, i));
      }
    }
    return 0;
  }

  // Rule-space selection (docs/language.md, "Rule-space selection"; Friedman & Stamos III-G):
  // every candidate's pattern and guard is tried in file order; among the matches with a key,
  // the one whose key is nearest (Euclidean) to the `select nearest` point evaluated with its own
  // bindings wins, ties going to the earlier production; without a keyed match, the first match.
  std::uint32_t choose_nearest(std::size_t i, std::uint32_t b, std::uint32_t e, double* slots,
                               LazyRng& rng) const {
    std::uint32_t best = e, first = e;
    double best_d2 = 0;
    for (std::uint32_t k = b; k < e; ++k) {
      const ir::Production& p = g.productions[table.index[k]];
      if (!match(p, i, slots)) continue;
      try {
        if (p.guard != ir::kNoCode && eval(g, p.guard, slots, rng) == 0) continue;
        if (p.key.empty()) {
          if (first == e) first = k;
          continue;
        }
        double d2 = 0;
        for (std::size_t c = 0; c < p.key.size(); ++c) {
          const double d = eval(g, p.query[c], slots, rng) - p.key[c];
          d2 += d * d;
        }
        if (best == e || d2 < best_d2) {
          best = k;
          best_d2 = d2;
        }
      } catch (const ExprError& err) {
        throw DeriveError(describe(g, p, err, info, i));
      }
    }
    const std::uint32_t chosen = best != e ? best : first;
    if (chosen == e) return 0;
    const ir::Production& p = g.productions[table.index[chosen]];
    match(p, i, slots);  // the slots of the chosen production
    try {
      return alternative(p, slots, rng);
    } catch (const ExprError& err) {
      throw DeriveError(describe(g, p, err, info, i));
    }
  }

  // The chosen production's alternative + 1: its only one when deterministic (no draw), else the
  // stochastic choice.
  std::uint32_t alternative(const ir::Production& p, const double* slots, LazyRng& rng) const {
    if (p.alt_end - p.alt_begin == 1 && g.alternatives[p.alt_begin].probability == ir::kNoCode) {
      return p.alt_begin + 1;
    }
    return pick(p, slots, rng) + 1;
  }

  // Stochastic choice: alternative k with probability p_k / sum(p) (ABOP ch. 1.7).
  std::uint32_t pick(const ir::Production& p, const double* slots, LazyRng& rng) const {
    double w[64];
    double sum = 0;
    const std::uint32_t n = std::min<std::uint32_t>(p.alt_end - p.alt_begin, 64);
    for (std::uint32_t k = 0; k < n; ++k) {
      const ir::CodeId c = g.alternatives[p.alt_begin + k].probability;
      w[k] = c == ir::kNoCode ? 1.0 : eval(g, c, slots, rng);
      if (w[k] < 0) throw ExprError("negative probability", c);
      sum += w[k];
    }
    if (!(sum > 0))
      throw ExprError("the probabilities sum to zero", g.alternatives[p.alt_begin].probability);
    double u = rng.get().uniform01() * sum;
    for (std::uint32_t k = 0; k < n; ++k) {
      if (u < w[k]) return p.alt_begin + k;
      u -= w[k];
    }
    for (std::uint32_t k = n; k-- > 0;) {
      if (w[k] > 0) return p.alt_begin + k;  // rounding left u at the top end
    }
    return p.alt_begin;
  }

  // Per-chunk output sizes (filled by choose_chunk, then prefix-summed into offsets).
  std::vector<std::uint64_t> mods, pars, hits;

  // First sweep over chunk c: choose the alternative of every module that needs a choice and
  // count the output: the chunk's own modules and parameters plus, per rewritten module, what
  // its successor writes more than itself, so that a copied module costs one test. The counts
  // are table lookups on the choice, not branches on it: a stochastic choice is random, and a
  // branch on it would be mispredicted about every other time.
  void choose_chunk(std::size_t c) {
    const ir::SymbolId* sym = in.symbols_data();
    const std::uint16_t* low = in.lows_data();
    const SymbolPlan* plan = plans.data();
    const double* w = weights.data();
    const std::uint32_t* amods = out_mods.data();
    const std::uint32_t* apars = out_params.data();
    PodVector<std::uint32_t>& choice = (*choices)[c];
    choice.resize(choice.capacity());  // what earlier passes grew, without zero-filling
    std::uint32_t* put = choice.data();
    std::uint32_t* put_end = put + choice.size();
    const std::size_t b = c * kChunk, e = std::min(in.size(), b + kChunk);
    std::uint64_t m = e - b, p = in.begin(e) - in.begin(b), h = 0;  // wrap-around sums
    // The rewritten modules' offsets in the chunk, gathered without a branch per module: which
    // modules are copied follows the string's shape, which a stochastic grammar makes random.
    std::uint16_t to_choose[kChunk];
    std::size_t nchoose = 0;
    const std::uint8_t* rewritten = rewrites.data();
    for (std::size_t i = b; i < e; ++i) {
      to_choose[nchoose] = std::uint16_t(i - b);
      nchoose += rewritten[sym[i]];
    }
    for (std::size_t t = 0; t < nchoose; ++t) {
      const std::size_t i = b + to_choose[t];
      const SymbolPlan& pl = plan[sym[i]];
      const std::uint32_t np = std::uint16_t(low[i + 1] - low[i]);
      if (pl.fixed_for(np)) {
        m += std::uint64_t(pl.mods) - 1;
        p += std::uint64_t(pl.params) - np;
        ++h;
        continue;
      }
      const std::uint32_t a =
          pl.kind == SymbolPlan::Weighted && pl.takes(np)
              ? pl.alt + 1 +
                    pick_weighted(w + pl.weights, pl.params, pl.fallback,
                                  stream_from_prefix(stream, 2 * std::uint64_t(i)))
              : choose(i);
      if (put == put_end) {  // grows the chunk's choices (kept for the next pass)
        const std::size_t used = std::size_t(put - choice.data());
        choice.resize(std::max<std::size_t>(2 * used, 4096));
        put = choice.data() + used;
        put_end = choice.data() + choice.size();
      }
      *put++ = a;
      m += std::uint64_t(amods[a]) - 1;
      p += std::uint64_t(a == 0 ? np : apars[a]) - np;
      h += a != 0;
    }
    choice.resize(std::size_t(put - choice.data()));
    mods[c + 1] = m;
    pars[c + 1] = p;
    hits[c] = h;
  }

  // Where the second sweep writes: the output's raw arrays.
  struct Out {
    ir::SymbolId* sym;
    std::uint16_t* low;
    std::uint32_t* base;
    double* params;
    void begin(std::size_t o, std::uint32_t pofs) const {
      low[o] = std::uint16_t(pofs);
      if ((o & ((std::size_t(1) << kBlockShift) - 1)) == 0) base[o >> kBlockShift] = pofs;
    }
  };

  // Second sweep over chunk c: write its modules at the offsets mods[c], pars[c].
  void write_chunk(std::size_t c, ModuleString& out, const std::vector<std::uint32_t>* origins,
                   std::uint32_t* new_origins) const {
    double slots[ir::kMaxSlots];
    const Out w{out.symbols_data(), out.lows_data(), out.bases_data(), out.params_data()};
    const ir::SymbolId* sym = in.symbols_data();
    const std::uint16_t* low = in.lows_data();
    const double* iparams = in.params_data();
    const SymbolPlan* plan = plans.data();
    std::size_t o = mods[c];
    std::uint32_t pofs = std::uint32_t(pars[c]);
    const std::size_t b = c * kChunk, e = std::min(in.size(), b + kChunk);
    std::uint32_t ip = in.begin(b);  // module i's parameters in the input
    const std::uint32_t* choice = (*choices)[c].data();
    for (std::size_t i = b; i < e; ++i) {
      const ir::SymbolId s = sym[i];
      const SymbolPlan& pl = plan[s];
      const std::uint32_t np = std::uint16_t(low[i + 1] - low[i]);
      const std::uint32_t a = pl.kind == SymbolPlan::Copy ? 0
                              : pl.fixed_for(np)          ? pl.alt + 1
                                                          : *choice++;
      std::size_t count = 1;
      if (a == 0) {
        w.sym[o] = s;
        w.begin(o, pofs);
        for (std::uint32_t k = 0; k < np; ++k) w.params[pofs + k] = iparams[ip + k];
        pofs += np;
      } else {
        const ir::Alternative& alt = g.alternatives[a - 1];
        count = alt.succ_end - alt.succ_begin;
        write(i, a - 1, w, o, pofs, iparams + ip, slots);
        pofs += alt.out_params;
      }
      if (new_origins) std::fill_n(new_origins + o, count, (*origins)[i]);
      o += count;
      ip += np;
    }
  }

  // Writes module i (parameters x) 's successor at output module o, parameter pofs; arguments
  // draw from (seed, key, 2i+1). Inlined into the write sweep's loop: out of line it costs
  // (a) a fifth more per module (GCC's inliner left it out once the sweep itself was inlined).
  [[gnu::always_inline]] inline void write(std::size_t i, std::uint32_t alt_id, const Out& w,
                                           std::size_t o, std::uint32_t pofs, const double* x,
                                           double* slots) const {
    const ir::Alternative& alt = g.alternatives[alt_id];
    const ir::Production& p = g.productions[alt.production];
    if (p.has_context()) {
      match_production(g, p, in, ctx, i, slots);  // re-binds the slots chosen in the first sweep
    } else if (!p.predecessor.any_params) {       // the first sweep matched the count
      for (std::uint32_t k = 0; k < p.predecessor.nparams; ++k) {
        slots[p.predecessor.first_slot + k] = x[k];
      }
    }
    LazyRng rng(stream, 2 * std::uint64_t(i) + 1);
    const std::uint32_t n = alt.succ_end - alt.succ_begin;
    const ir::SymbolId* sym = succ.symbols.data() + succ.first_module[alt_id];
    const std::uint32_t* offset = succ.offsets.data() + succ.first_module[alt_id];
    for (std::uint32_t m = 0; m < n; ++m) {
      w.sym[o + m] = sym[m];
      w.low[o + m] = std::uint16_t(pofs + offset[m]);
    }
    constexpr std::size_t kMask = (std::size_t(1) << kBlockShift) - 1;
    for (std::size_t q = (o + kMask) & ~kMask; q < o + n; q += kMask + 1) {
      w.base[q >> kBlockShift] = pofs + offset[q - o];  // a block starts in the successor
    }
    const ArgOp* arg = succ.args.data() + succ.first_arg[alt_id];
    double* const out = w.params + pofs;
    try {
      for (std::uint32_t k = 0; k < alt.out_params; ++k) out[k] = value(arg[k], out, slots, rng);
    } catch (const ExprError& err) {
      throw DeriveError(describe(g, p, err, info, i));
    }
  }

  // eval() (compiler/expr_vm.h) for a flattened argument.
  double value(const ArgOp& a, const double* first_param, const double* slots, LazyRng& rng) const {
    switch (a.kind) {
      case ArgOp::Same:
        return first_param[a.same];
      case ArgOp::Constant:
        return a.value;
      case ArgOp::Param:
        return slots[a.slot];
      case ArgOp::ParamOpConst: {
        const double x = slots[a.slot];
        const double r = a.op == ir::Op::Add   ? x + a.value
                         : a.op == ir::Op::Sub ? x - a.value
                         : a.op == ir::Op::Mul ? x * a.value
                                               : x / a.value;
        if (std::isfinite(r)) return r;
        break;
      }
      case ArgOp::General:
        break;
    }
    return run_code(g, a.code, slots, rng);
  }
};

// Runs body(c) for chunks c = 0..nchunks-1 on `threads` threads; rethrows the error of the
// lowest chunk so that the reported error does not depend on scheduling.
template <typename Body>
void for_chunks(std::size_t nchunks, int threads, const Body& body) {
  std::vector<std::exception_ptr> errors(nchunks);
  auto run = [&](std::size_t c) {
    try {
      body(c);
    } catch (...) {
      errors[c] = std::current_exception();
    }
  };
  if (nchunks == 1 || threads == 1) {
    for (std::size_t c = 0; c < nchunks; ++c) run(c);
  } else {
    run_chunks_parallel(nchunks, threads, run);
  }
  for (auto& e : errors) {
    if (e) std::rethrow_exception(e);
  }
}

std::string gigabytes(double bytes) {
  char buf[32];
  if (bytes < 1e9) {
    std::snprintf(buf, sizeof buf, "%.2f MB", bytes / 1e6);
  } else {
    std::snprintf(buf, sizeof buf, "%.2f GB", bytes / 1e9);
  }
  return buf;
}

void check_limits(const PassInfo& info, std::uint64_t modules, std::uint64_t params,
                  std::size_t working) {
  if (modules > info.max_modules) {
    throw DeriveError(info.where + ": the string would grow to " + std::to_string(modules) +
                      " modules, more than the limit of " + std::to_string(info.max_modules) +
                      " (--max-modules)");
  }
  const std::uint64_t limit = info.max_bytes ? info.max_bytes : default_memory_limit();
  const double need = double(working) + double(modules) * module_bytes(0) + double(modules) / 256 +
                      double(params) * 8;  // 4 bytes of block offset per 1024 modules
  if (need > double(limit) || params > 0xffffffffull) {
    throw DeriveError(info.where + ": the string would need " + gigabytes(need) + " (" +
                      std::to_string(modules) + " modules), more than the memory limit of " +
                      gigabytes(double(limit)) + " (--max-memory)");
  }
  if (info.peak_bytes) *info.peak_bytes = std::max(*info.peak_bytes, std::size_t(need));
}

}  // namespace

PassScratch::PassScratch() = default;
PassScratch::~PassScratch() = default;

// Asked once per process: sysconf(_SC_PHYS_PAGES) is a system call (sysinfo), which every pass
// would otherwise pay.
std::uint64_t default_memory_limit() {
  static const std::uint64_t limit = [] {
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    if (pages <= 0 || page <= 0) return std::uint64_t(8) << 30;
    return std::uint64_t(double(pages) * double(page) * 0.8);
  }();
  return limit;
}

bool apply_pass(const ir::Grammar& g, ir::Kind kind, const ModuleString& in, ModuleString& out,
                const PassInfo& info, std::vector<std::uint32_t>* origins) {
  const ir::Table& table = g.table(kind);
  const std::size_t n = in.size();
  if (table.empty() || n == 0) return false;
  ContextTables ctx_tables;
  if (table.has_context) ctx_tables.build(in, g.ignored, table.has_left, table.has_right);
  PassScratch own;
  PassScratch& scratch = info.scratch ? *info.scratch : own;
  if (!scratch.plan || scratch.plan->grammar != &g) {
    check_successor_arity(g);
    scratch.plan = std::make_unique<derive_plan::PassPlan>(g);
  }
  const derive_plan::PassPlan::Table& planned = scratch.plan->table(kind);
  Pass pass{g,
            table,
            in,
            table.has_context ? &ctx_tables : nullptr,
            info,
            stream_prefix(info.seed, info.key),
            planned.plans,
            planned.weights,
            scratch.plan->succ,
            scratch.plan->out_mods,
            scratch.plan->out_params,
            planned.rewrites,
            &scratch.choices,
            {},
            {},
            {}};

  const std::size_t nchunks = (n + kChunk - 1) / kChunk;
  if (scratch.choices.size() < nchunks) scratch.choices.resize(nchunks);
  pass.mods.assign(nchunks + 1, 0);
  pass.pars.assign(nchunks + 1, 0);
  pass.hits.assign(nchunks, 0);
  for_chunks(nchunks, info.threads, [&](std::size_t c) { pass.choose_chunk(c); });
  if (std::all_of(pass.hits.begin(), pass.hits.end(), [](std::uint64_t h) { return h == 0; })) {
    return false;
  }
  for (std::size_t c = 0; c < nchunks; ++c) {  // output offsets of every chunk
    pass.mods[c + 1] += pass.mods[c];
    pass.pars[c + 1] += pass.pars[c];
  }
  const std::uint64_t total = pass.mods[nchunks], total_params = pass.pars[nchunks];
  std::size_t choice_bytes = 0;
  for (std::size_t c = 0; c < nchunks; ++c) choice_bytes += scratch.choices[c].capacity() * 4;
  const std::size_t working =
      in.bytes() + choice_bytes + ctx_tables.bytes() + (origins ? (n + total) * 4 : 0);
  check_limits(info, total, total_params, working);

  std::vector<std::uint32_t> new_origins;
  try {
    out.clear();
    if (info.scratch && (out.capacity() < total || out.params_capacity() < total_params)) {
      // derive()'s two strings take turns as output: with room for two more passes that grow
      // the string as much as this one did (at least 4 x this output, at most 16 x), a buffer
      // serves again two passes later and only its new part is paged in (a string that doubles
      // per step then pages in 1.5 x its final size instead of 2 x). Untouched room costs
      // address space only; where that is short, the exact size is taken.
      const double growth = double(total) / double(n);
      const double room = std::clamp(growth * growth * 1.05, 4.0, 16.0);
      try {
        out.reserve(std::size_t(room * double(total)), std::size_t(room * double(total_params)));
      } catch (const std::bad_alloc&) {
      } catch (const std::length_error&) {
      }
    }
    out.resize_for_fill(total, total_params);
    if (origins) new_origins.resize(total);
  } catch (const std::bad_alloc&) {
    throw DeriveError(info.where + ": out of memory for a string of " + std::to_string(total) +
                      " modules");
  }
  for_chunks(nchunks, info.threads, [&](std::size_t c) {
    pass.write_chunk(c, out, origins, origins ? new_origins.data() : nullptr);
  });
  if (origins) origins->swap(new_origins);
  return true;
}

bool apply_cut(ModuleString& s) {
  const ir::SymbolId* sym = s.symbols_data();
  if (std::find(sym, sym + s.size(), ir::kCut) == sym + s.size()) return false;
  ModuleString out;
  out.reserve(s.size(), s.param_count());
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.symbol(i) != ir::kCut) {
      out.push(s.symbol(i), s.params(i), s.nparams(i));
      continue;
    }
    // Skip to the `]` closing this branch (kept), or to the end of the string.
    int depth = 0;
    std::size_t j = i + 1;
    for (; j < s.size(); ++j) {
      if (s.symbol(j) == ir::kPush) ++depth;
      if (s.symbol(j) == ir::kPop && depth-- == 0) break;
    }
    i = j - 1;
  }
  s = std::move(out);
  return true;
}

void check_branches(const ir::Grammar& g, const ModuleString& s, ir::Kind kind,
                    const std::string& where) {
  std::string error = unclosed_branch_error(g, s, kind, where);
  if (!error.empty()) throw DeriveError(error);
}

ModuleString axiom_string(const ir::Grammar& g) {
  ModuleString s;
  for (const ir::SuccModule& m : g.axiom) {
    if (m.nargs > kMaxModuleParams) {
      throw DeriveError("the axiom holds a module with " + std::to_string(m.nargs) +
                        " parameters; a module holds at most " + std::to_string(kMaxModuleParams));
    }
    double p[kMaxModuleParams];
    for (std::uint32_t a = 0; a < m.nargs; ++a) {
      LazyRng rng(g.settings.seed, 0, 0);
      p[a] = eval(g, g.args[m.arg_begin + a], nullptr, rng);
    }
    s.push(m.symbol, p, m.nargs);
  }
  return s;
}

namespace {

// Decomposition after a step: repeated passes until no decomposition applies, at most
// max_depth of them (lpfg's decomposition depth), then the cut.
void decompose_and_cut(const ir::Grammar& g, ModuleString& s, ModuleString& scratch, PassInfo info,
                       int step, bool may_cut) {
  const int limit = std::max(1, std::min(g.settings.max_depth, 255));
  for (int round = 1; !g.decompose.empty(); ++round) {
    if (round > limit) {
      throw DeriveError("decomposition after step " + std::to_string(step) +
                        " still applies after max_depth = " + std::to_string(limit) + " rounds");
    }
    info.key = std::uint64_t(step) * 512 + round;
    info.where =
        "decomposition round " + std::to_string(round) + " of step " + std::to_string(step);
    if (!apply_pass(g, ir::Kind::Decompose, s, scratch, info)) break;
    std::swap(s, scratch);
  }
  if (may_cut) apply_cut(s);
}

// Whether a `%` can ever appear in the string (else the cut's scan is skipped).
bool may_cut(const ir::Grammar& g) {
  auto is_cut = [](const ir::SuccModule& m) { return m.symbol == ir::kCut; };
  return std::any_of(g.axiom.begin(), g.axiom.end(), is_cut) ||
         std::any_of(g.successors.begin(), g.successors.end(), is_cut);
}

}  // namespace

ModuleString derive(const ir::Grammar& g, const DeriveOptions& options, DeriveStats* stats) {
  const auto t0 = std::chrono::steady_clock::now();
  const int steps = options.steps.value_or(g.settings.derive);
  if (steps < 0) throw DeriveError("the number of steps must not be negative");
  std::size_t peak = 0;
  PassInfo info;
  info.seed = options.seed.value_or(g.settings.seed);
  info.max_modules = options.max_modules;
  info.max_bytes = options.max_bytes;
  info.threads = options.threads;
  info.peak_bytes = &peak;
  PassScratch scratch;
  info.scratch = &scratch;

  ModuleString s = axiom_string(g), next;
  if (s.size() > options.max_modules) throw DeriveError("the axiom is longer than --max-modules");
  const bool cut = may_cut(g);
  check_branches(g, s, ir::Kind::Rewrite, "the axiom");
  const bool rewrite_unbalances = may_unbalance_branches(g, ir::Kind::Rewrite);
  const bool decompose_unbalances = may_unbalance_branches(g, ir::Kind::Decompose);
  decompose_and_cut(g, s, next, info, 0, cut);
  if (decompose_unbalances) check_branches(g, s, ir::Kind::Decompose, "decomposition of the axiom");
  if (stats) stats->lengths.assign(1, s.size());
  for (int step = 1; step <= steps; ++step) {
    info.key = std::uint64_t(step) * 512;
    info.where = "step " + std::to_string(step);
    if (apply_pass(g, ir::Kind::Rewrite, s, next, info)) {
      std::swap(s, next);
      next.clear();
      if (rewrite_unbalances) check_branches(g, s, ir::Kind::Rewrite, info.where);
    }
    decompose_and_cut(g, s, next, info, step, cut);
    if (decompose_unbalances) {
      check_branches(g, s, ir::Kind::Decompose, "decomposition after step " + std::to_string(step));
    }
    if (stats) stats->lengths.push_back(s.size());
  }
  peak = std::max(peak, s.bytes());
  if (stats) {
    stats->steps = steps;
    stats->peak_bytes = peak;
    stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  return s;
}

}  // namespace ramus
