#include "lsp/module_info.h"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

namespace ramus::lsp {

namespace {

template <typename F>
void each_production(const Analysis& analysis, F&& f) {
  for (const ast::File& file : analysis.program().files) {
    for (const ast::Decl& d : file.decls) {
      const auto* l = std::get_if<ast::LSystem>(&d);
      if (l == nullptr) continue;
      for (const ast::LSystemItem& item : l->items) {
        if (const auto* p = std::get_if<ast::Production>(&item)) f(*p);
      }
    }
  }
}

}  // namespace

std::string pattern_text(const ast::ModulePattern& p) {
  std::string s = p.name;
  if (!p.has_parens) return s;
  s += '(';
  for (std::size_t i = 0; i < p.params.size(); ++i) s += (i ? ", " : "") + p.params[i].name;
  return s + ')';
}

std::vector<const ast::Production*> productions_of(const Analysis& analysis,
                                                   const std::string& name) {
  std::vector<const ast::Production*> out;
  each_production(analysis, [&](const ast::Production& p) {
    if (p.predecessor.name == name) out.push_back(&p);
  });
  return out;
}

std::string module_signature(const Analysis& analysis, const std::string& name) {
  if (const Definition* d = analysis.find(name, {Definition::Kind::Module})) {
    return pattern_text(*d->pattern);
  }
  for (const ast::Production* p : productions_of(analysis, name)) {
    if (p->predecessor.has_parens) return pattern_text(p->predecessor);
  }
  return name;
}

std::vector<ModuleName> module_names(const Analysis& analysis) {
  std::vector<ModuleName> out;
  std::unordered_map<std::string, std::size_t> index;  // name -> its place in `out`
  std::unordered_set<std::string> declared;
  auto add = [&](const std::string& n, const ast::ModulePattern* pattern) {
    if (n.empty()) return;
    auto [it, fresh] = index.try_emplace(n, out.size());
    if (fresh) out.push_back({n, n});
    // The declaration wins; else the first pattern written with parentheses.
    ModuleName& m = out[it->second];
    if (pattern && !declared.count(n) && m.signature == n && pattern->has_parens)
      m.signature = pattern_text(*pattern);
  };
  for (const Definition& d : analysis.definitions()) {
    if (d.kind != Definition::Kind::Module) continue;
    add(d.name, d.pattern);
    declared.insert(d.name);
  }
  each_production(analysis,
                  [&](const ast::Production& p) { add(p.predecessor.name, &p.predecessor); });
  for (const ast::File& file : analysis.program().files) {
    for (const ast::Decl& d : file.decls) {
      const auto* l = std::get_if<ast::LSystem>(&d);
      if (l == nullptr) continue;
      for (const ast::LSystemItem& item : l->items) {
        if (const auto* a = std::get_if<ast::Axiom>(&item)) {
          for (const ast::ModuleCall& c : a->modules) add(c.name, nullptr);
        } else if (const auto* p = std::get_if<ast::Production>(&item)) {
          for (const ast::Alternative& alt : p->alternatives) {
            for (const ast::ModuleCall& c : alt.successor) add(c.name, nullptr);
          }
        }
      }
    }
  }
  return out;
}

}  // namespace ramus::lsp
