#include "compiler/bracket_balance.h"

namespace ramus {

namespace {

// Whether the successor [begin, end) holds a closing symbol with no opening one before it.
bool has_unmatched_close(const ir::Grammar& g, std::uint32_t begin, std::uint32_t end,
                         ir::TurtleOp open, ir::TurtleOp close) {
  int depth = 0;
  for (std::uint32_t m = begin; m < end; ++m) {
    const ir::TurtleOp op = g.symbols[g.successors[m].symbol].turtle;
    if (op == open) ++depth;
    if (op == close && depth-- == 0) return true;
  }
  return false;
}

bool production_unbalanced(const ir::Grammar& g, const ir::Production& p, ir::TurtleOp open,
                           ir::TurtleOp close) {
  for (std::uint32_t a = p.alt_begin; a < p.alt_end; ++a) {
    const ir::Alternative& alt = g.alternatives[a];
    if (has_unmatched_close(g, alt.succ_begin, alt.succ_end, open, close)) return true;
  }
  return false;
}

std::string list(const ir::Grammar& g, ir::TurtleOp open, ir::TurtleOp close, bool any_kind,
                 ir::Kind kind) {
  std::string out;
  int n = 0;
  for (const ir::Production& p : g.productions) {
    if (!any_kind && p.kind != kind) continue;
    if (!production_unbalanced(g, p, open, close)) continue;
    if (++n > 3) {
      out += ", ...";
      break;
    }
    out += n == 1 ? " -- written by production " : ", or ";
    out += "`" + p.text + "`";
    if (p.where < g.locations.size()) out += " (" + g.locations[p.where] + ")";
  }
  return out;
}

}  // namespace

bool may_unbalance_branches(const ir::Grammar& g, ir::Kind kind) {
  for (const ir::Production& p : g.productions) {
    if (p.kind == kind && production_unbalanced(g, p, ir::TurtleOp::Push, ir::TurtleOp::Pop)) {
      return true;
    }
  }
  return false;
}

std::string unclosed_branch_error(const ir::Grammar& g, const ModuleString& s, ir::Kind kind,
                                  const std::string& where) {
  std::size_t depth = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const ir::SymbolId sym = s.symbol(i);
    if (sym == ir::kPush) ++depth;
    if (sym != ir::kPop) continue;
    if (depth-- > 0) continue;
    return where + ": `]` at module " + std::to_string(i) + " closes no branch" +
           list(g, ir::TurtleOp::Push, ir::TurtleOp::Pop, false, kind);
  }
  return {};
}

std::string unbalanced_productions(const ir::Grammar& g, ir::SymbolId symbol) {
  const ir::TurtleOp op = g.symbols[symbol].turtle;
  if (op == ir::TurtleOp::Pop) {
    return list(g, ir::TurtleOp::Push, ir::TurtleOp::Pop, true, ir::Kind::Rewrite);
  }
  if (op == ir::TurtleOp::PolygonEnd) {
    return list(g, ir::TurtleOp::PolygonBegin, ir::TurtleOp::PolygonEnd, true, ir::Kind::Rewrite);
  }
  return {};
}

}  // namespace ramus
