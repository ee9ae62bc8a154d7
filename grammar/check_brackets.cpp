// Unbalanced brackets in an lsystem's axiom and successors (E0309, E0310): a `]` that closes no
// branch was silently skipped by the turtle before, and a `[` never closed leaves the turtle in a
// branch; both are mistakes every grammar author makes (L-Py reports them too).
//
// Branches must balance within every successor. Polygons (ABOP 5.2) may not: the lily of the
// valley opens its polygons in one production (`A -> [&GA{.].`) and closes them in another
// (`B -> B&.G.}`), so an unmatched `{` or `}` is an error only when no other rule of the block
// leaves the opposite brace open for it.
#include "grammar/detail/check_context.h"

namespace ramus::detail {
namespace {

// The unmatched openers and closers of one module sequence, for one pair of brackets.
struct Unmatched {
  std::vector<const ast::ModuleCall*> open, close;
};

Unmatched unmatched(const ast::ModuleSeq& seq, std::string_view open, std::string_view close) {
  Unmatched u;
  for (const ast::ModuleCall& m : seq) {
    if (m.name == open) {
      u.open.push_back(&m);
    } else if (m.name == close) {
      if (u.open.empty()) {
        u.close.push_back(&m);
      } else {
        u.open.pop_back();
      }
    }
  }
  return u;
}

struct Rule {
  const ast::ModuleSeq* modules;
  SourceSpan span;  // the axiom or the production
  bool axiom;
};

std::string rule_name(const Rule& r) { return r.axiom ? "the axiom" : "this production"; }

}  // namespace

void check_brackets(CheckContext& cx, const ast::LSystem& ls) {
  std::vector<Rule> rules;
  for (const ast::LSystemItem& item : ls.items) {
    if (const auto* a = std::get_if<ast::Axiom>(&item))
      rules.push_back({&a->modules, a->span, true});
    if (const auto* p = std::get_if<ast::Production>(&item)) {
      for (const ast::Alternative& alt : p->alternatives) {
        rules.push_back({&alt.successor, p->span, false});
      }
    }
  }
  for (const Rule& r : rules) {
    const Unmatched u = unmatched(*r.modules, "[", "]");
    for (const ast::ModuleCall* m : u.close) {
      cx.error(DiagCode::UnbalancedBranch, m->span, "']' closes no branch");
      cx.note(r.span, "in " + rule_name(r) + ", which has no '[' open here");
    }
    for (const ast::ModuleCall* m : u.open) {
      cx.error(DiagCode::UnbalancedBranch, m->span, "'[' opens a branch that is never closed");
      cx.note(r.span, "add its ']' in " + rule_name(r));
    }
  }
  // Polygons: the block's rules together.
  bool any_open = false, any_close = false;
  std::vector<Unmatched> braces;
  for (const Rule& r : rules) {
    braces.push_back(unmatched(*r.modules, "{", "}"));
    any_open = any_open || !braces.back().open.empty();
    any_close = any_close || !braces.back().close.empty();
  }
  for (std::size_t i = 0; i < rules.size(); ++i) {
    if (!any_open) {
      for (const ast::ModuleCall* m : braces[i].close) {
        cx.error(DiagCode::UnbalancedPolygon, m->span, "'}' closes no polygon");
        cx.note(rules[i].span, "neither " + rule_name(rules[i]) +
                                   " nor any other rule of the lsystem leaves a '{' open");
      }
    }
    if (!any_close) {
      for (const ast::ModuleCall* m : braces[i].open) {
        cx.error(DiagCode::UnbalancedPolygon, m->span, "'{' opens a polygon that is never closed");
        cx.note(rules[i].span, "neither " + rule_name(rules[i]) +
                                   " nor any other rule of the lsystem has a '}' to close it");
      }
    }
  }
}

}  // namespace ramus::detail
