// Warnings about productions that never apply (root file only):
//  W0002 its predecessor appears neither in the axiom nor in any successor reachable from it;
//  W0003 an earlier production of the same kind, predecessor and contexts has no guard, so it
//        always wins (the first matching production applies, docs/language.md). Not given under
//        `select nearest`, where the nearest rule applies rather than the first.
// Both are linear in the size of the block: hash maps keyed by module name / production shape.
#include <unordered_set>

#include "grammar/detail/check_context.h"

namespace ramus::detail {
namespace {

std::string shape_key(const CheckContext& cx, std::uint32_t file, const ast::Production& p) {
  std::string key(1, char('0' + int(p.kind)));
  auto add = [&](const ast::ModulePattern& m) {
    std::vector<std::string> parts = module_parts(cx, file, m.name);
    if (parts.empty()) parts = {m.name};
    for (std::size_t i = 0; i < parts.size(); ++i) {
      key += ' ';
      key += parts[i];
      key += '/';
      key += std::to_string(i + 1 == parts.size() ? m.params.size() : 0);
    }
  };
  for (const ast::ModulePattern& m : p.left_context) add(m);
  key += " <";
  add(p.predecessor);
  key += " >";
  for (const ast::ModulePattern& m : p.right_context) add(m);
  return key;
}

void warn_unreachable(CheckContext& cx, std::uint32_t file, const ast::LSystem& ls,
                      const std::vector<const ast::Production*>& prods) {
  const ast::Axiom* axiom = nullptr;
  for (const ast::LSystemItem& item : ls.items) {
    if (!axiom) axiom = std::get_if<ast::Axiom>(&item);
  }
  if (!axiom) return;  // E0305 already
  std::unordered_map<std::string, std::vector<std::size_t>> by_predecessor;
  for (std::size_t i = 0; i < prods.size(); ++i) {
    std::vector<std::string> parts = module_parts(cx, file, prods[i]->predecessor.name);
    if (parts.size() == 1) by_predecessor[parts[0]].push_back(i);
  }
  std::unordered_set<std::string> seen;
  std::vector<std::string> work;
  auto appear = [&](const ast::ModuleSeq& seq) {
    for (const ast::ModuleCall& call : seq) {
      for (std::string& part : module_parts(cx, file, call.name)) {
        if (seen.insert(part).second) work.push_back(std::move(part));
      }
    }
  };
  appear(axiom->modules);
  std::vector<bool> reached(prods.size(), false);
  while (!work.empty()) {
    std::string name = std::move(work.back());
    work.pop_back();
    auto it = by_predecessor.find(name);
    if (it == by_predecessor.end()) continue;
    for (std::size_t i : it->second) {
      reached[i] = true;
      for (const ast::Alternative& alt : prods[i]->alternatives) appear(alt.successor);
    }
  }
  for (std::size_t i = 0; i < prods.size(); ++i) {
    const ast::ModulePattern& pred = prods[i]->predecessor;
    if (reached[i] || module_parts(cx, file, pred.name).size() != 1) continue;
    cx.error(DiagCode::UnusedProduction, pred.span,
             "this production never applies: '" + pred.name +
                 "' appears neither in the axiom nor in any successor that can occur");
  }
}

void warn_shadowed(CheckContext& cx, std::uint32_t file,
                   const std::vector<const ast::Production*>& prods) {
  std::unordered_map<std::string, const ast::Production*> always;  // shape -> unguarded rule
  for (const ast::Production* p : prods) {
    std::string key = shape_key(cx, file, *p);
    auto it = always.find(key);
    if (it != always.end()) {
      cx.error(DiagCode::ShadowedProduction, p->predecessor.span,
               "this production never applies: an earlier production for '" + p->predecessor.name +
                   "' with the same contexts has no guard");
      cx.note(it->second->span, "this production always applies first");
      continue;
    }
    if (!p->guard) always.emplace(std::move(key), p);
  }
}

}  // namespace

void check_lsystem_flow(CheckContext& cx, std::uint32_t file, const ast::LSystem& ls) {
  if (!cx.warn_in(file)) return;
  std::vector<const ast::Production*> prods;
  bool nearest = false;
  for (const ast::LSystemItem& item : ls.items) {
    if (const auto* p = std::get_if<ast::Production>(&item)) prods.push_back(p);
    if (const auto* s = std::get_if<ast::Select>(&item)) nearest = s->mode.name == "nearest";
  }
  warn_unreachable(cx, file, ls, prods);
  if (!nearest) warn_shadowed(cx, file, prods);
}

}  // namespace ramus::detail
