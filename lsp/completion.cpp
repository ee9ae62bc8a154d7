#include "lsp/completion.h"

#include "core/number_text.h"
#include "grammar/format.h"
#include "grammar/modules.h"
#include "lsp/cursor.h"
#include "lsp/language_words.h"
#include "lsp/module_info.h"

namespace ramus::lsp {

std::vector<CompletionItem> completion_at(const Analysis& a, const Position& position) {
  using K = Definition::Kind;
  std::vector<CompletionItem> items;
  auto word_items = [&](std::span<const Word> words, CompletionKind kind) {
    for (const Word& w : words) {
      items.push_back(
          {std::string(w.name), kind, std::string(w.signature), std::string(w.meaning)});
    }
  };
  if (const ast::File* root = a.root()) {
    if (const ast::Production* p = production_at(*root, a.offset_of(position))) {
      for (const auto* seq : {&p->left_context, &p->right_context}) {
        for (const ast::ModulePattern& m : *seq) {
          for (const ast::Identifier& id : m.params)
            items.push_back(
                {id.name, CompletionKind::Variable, "parameter of " + pattern_text(m), ""});
        }
      }
      for (const ast::Identifier& id : p->predecessor.params) {
        items.push_back({id.name, CompletionKind::Variable,
                         "parameter of " + pattern_text(p->predecessor), ""});
      }
    }
  }
  for (const Definition& d : a.definitions()) {
    if (d.kind != K::Const && d.kind != K::Param) continue;
    std::string detail =
        (d.kind == K::Param ? "param " : "const ") + d.name + " = " + format_expr(*d.value);
    if (std::optional<double> v = a.value_of(d.name)) {
      std::string text = shortest_text(*v);
      if (text != format_expr(*d.value)) detail += "  (" + text + ")";
    }
    items.push_back({d.name, CompletionKind::Constant, detail, a.comment_of(d.decl_span)});
  }
  for (const ModuleName& m : module_names(a)) {
    // Turtle symbols (F and f among them) are offered below with their meaning.
    if (!is_identifier(m.name) || find_word(turtle_symbols(), m.name)) continue;
    items.push_back({m.name, CompletionKind::Class, "module " + m.signature, ""});
  }
  for (const Definition& d : a.definitions()) {
    if (d.kind == K::Piece || d.kind == K::Rim)
      items.push_back({d.name, CompletionKind::Property, d.kind == K::Piece ? "piece" : "rim", ""});
  }
  word_items(builtin_functions(), CompletionKind::Function);
  word_items(turtle_symbols(), CompletionKind::Operator);
  word_items(lsystem_settings(), CompletionKind::Property);
  word_items(keywords(), CompletionKind::Keyword);
  return items;
}

}  // namespace ramus::lsp
