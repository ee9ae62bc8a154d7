#include "compiler/context.h"

namespace ramus {

void ContextTables::build(const ModuleString& s, const std::vector<std::uint8_t>& ignored,
                          bool need_left, bool need_right) {
  const std::uint32_t n = std::uint32_t(s.size());
  const ir::SymbolId* sym = s.symbols_data();
  partner.assign(n, kNone);
  left.clear();
  right.clear();
  if (need_left) left.resize(n);
  if (need_right) right.resize(n);
  std::vector<std::uint32_t> open;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (sym[i] == ir::kPush) {
      open.push_back(i);
    } else if (sym[i] == ir::kPop && !open.empty()) {
      partner[i] = open.back();
      partner[open.back()] = i;
      open.pop_back();
    }
  }
  // left[i]: scan left from i, skipping ignored modules, `[` (leave the branch to its parent)
  // and whole branches `[...]` ending at a `]`. Each step reuses an already computed entry.
  std::uint32_t prev = kNone;  // nearest visible module before i
  for (std::uint32_t i = 0; need_left && i < n; ++i) {
    std::uint32_t j = prev;
    if (j != kNone && sym[j] == ir::kPush) {
      j = left[j];
    } else if (j != kNone && sym[j] == ir::kPop) {
      j = partner[j] == kNone ? kNone : left[partner[j]];
    }
    left[i] = j;
    if (!ignored[sym[i]]) prev = i;
  }
  // right[i]: scan right, skipping ignored modules and lateral branches; a `]` is returned as
  // is (the caller fails there), an unmatched `[` runs to the end of the string.
  std::uint32_t next = kNone;
  for (std::uint32_t i = n; need_right && i-- > 0;) {
    std::uint32_t j = next;
    if (j != kNone && sym[j] == ir::kPush) {
      j = partner[j] == kNone ? kNone : right[partner[j]];
    }
    right[i] = j;
    if (!ignored[sym[i]]) next = i;
  }
}

namespace {

inline bool bind(const ir::Pattern& pat, const ModuleString& s, std::size_t i, double* slots) {
  if (s.symbol(i) != pat.symbol) return false;
  if (pat.any_params) return true;
  if (s.nparams(i) != pat.nparams) return false;
  const double* p = s.params(i);
  for (std::uint32_t k = 0; k < pat.nparams; ++k) slots[pat.first_slot + k] = p[k];
  return true;
}

// The next visible position after i without skipping a `[` (for a `[` in the pattern).
std::uint32_t next_raw(const ModuleString& s, const std::vector<std::uint8_t>& ignored,
                       std::uint32_t i) {
  for (std::uint32_t j = i + 1; j < s.size(); ++j) {
    if (!ignored[s.symbol(j)]) return j;
  }
  return kNone;
}

// The `]` that closes the branch holding position i (kNone at the top level).
std::uint32_t branch_end(const ModuleString& s, const ContextTables& ctx, std::uint32_t i) {
  for (std::uint32_t j = i + 1; j < s.size(); ++j) {
    if (s.symbol(j) == ir::kPop) return j;
    if (s.symbol(j) == ir::kPush) {
      if (ctx.partner[j] == kNone) return kNone;
      j = ctx.partner[j];
    }
  }
  return kNone;
}

bool match_right(const ir::Grammar& g, const ir::Production& p, const ModuleString& s,
                 const ContextTables& ctx, std::uint32_t i, double* slots) {
  std::uint32_t pos = i;
  std::uint32_t entered[32];
  int depth = 0;
  for (const ir::Pattern& pat : p.right) {
    if (pat.symbol == ir::kPush) {
      std::uint32_t j = next_raw(s, g.ignored, pos);
      if (j == kNone || s.symbol(j) != ir::kPush || depth == 32) return false;
      entered[depth++] = j;
      pos = j;
    } else if (pat.symbol == ir::kPop) {
      std::uint32_t j = depth > 0 ? ctx.partner[entered[--depth]] : branch_end(s, ctx, pos);
      if (j == kNone) return false;
      pos = j;
    } else {
      std::uint32_t j = ctx.right[pos];
      if (j == kNone || !bind(pat, s, j, slots)) return false;
      pos = j;
    }
  }
  return true;
}

}  // namespace

bool match_production(const ir::Grammar& g, const ir::Production& p, const ModuleString& s,
                      const ContextTables* ctx, std::size_t i, double* slots) {
  if (!bind(p.predecessor, s, i, slots)) return false;
  if (!p.has_context()) return true;
  std::uint32_t pos = std::uint32_t(i);
  for (std::size_t k = p.left.size(); k-- > 0;) {
    std::uint32_t j = ctx->left[pos];
    if (j == kNone || !bind(p.left[k], s, j, slots)) return false;
    pos = j;
  }
  return p.right.empty() || match_right(g, p, s, *ctx, std::uint32_t(i), slots);
}

}  // namespace ramus
