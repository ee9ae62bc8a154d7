#include "lsp/document_symbols.h"

#include "grammar/format.h"
#include "lsp/module_info.h"

namespace ramus::lsp {

namespace {

DocumentSymbol symbol(const Analysis& a, std::string name, std::string detail, SymbolKind kind,
                      const SourceSpan& whole, const SourceSpan& name_span) {
  DocumentSymbol s;
  s.name = name.empty() ? "(unnamed)" : std::move(name);  // clients reject empty names
  s.detail = std::move(detail);
  s.kind = kind;
  s.range = a.range(whole);
  s.selection_range = a.range(name_span);
  // The specification asks the selection to lie inside the range.
  if (whole.begin > name_span.begin || whole.end < name_span.end) s.range = s.selection_range;
  return s;
}

SourceSpan name_of(const ast::ModulePattern& p) {
  return {p.span.file, p.span.begin, p.span.begin + std::uint32_t(p.name.size())};
}

std::vector<DocumentSymbol> lsystem_items(const Analysis& a, const ast::LSystem& l) {
  std::vector<DocumentSymbol> out;
  for (const ast::LSystemItem& item : l.items) {
    if (const auto* ax = std::get_if<ast::Axiom>(&item)) {
      out.push_back(symbol(a, "axiom", "", SymbolKind::Property, ax->span, ax->span));
    } else if (const auto* p = std::get_if<ast::Production>(&item)) {
      const char* kind = p->kind == ast::ProductionKind::Interpret   ? "interpret"
                         : p->kind == ast::ProductionKind::Decompose ? "decompose"
                                                                     : "production";
      std::string detail = kind;
      if (p->guard) detail += " : " + format_expr(*p->guard);
      out.push_back(symbol(a, pattern_text(p->predecessor), detail, SymbolKind::Function, p->span,
                           name_of(p->predecessor)));
    }
  }
  return out;
}

}  // namespace

std::vector<DocumentSymbol> document_symbols(const Analysis& a) {
  std::vector<DocumentSymbol> out;
  const ast::File* root = a.root();
  if (root == nullptr) return out;
  for (const ast::Decl& d : root->decls) {
    if (const auto* im = std::get_if<ast::Import>(&d)) {
      out.push_back(symbol(a, im->path, "import", SymbolKind::File, im->span, im->span));
    } else if (const auto* c = std::get_if<ast::ConstDecl>(&d)) {
      for (const ast::Binding& b : c->bindings) {
        out.push_back(symbol(a, b.name.name, format_expr(b.value),
                             c->is_param ? SymbolKind::Variable : SymbolKind::Constant, c->span,
                             b.name.span));
      }
    } else if (const auto* m = std::get_if<ast::ModuleDecl>(&d)) {
      for (const ast::ModulePattern& p : m->modules) {
        out.push_back(
            symbol(a, pattern_text(p), "module", SymbolKind::Struct, m->span, name_of(p)));
      }
    } else if (const auto* l = std::get_if<ast::LSystem>(&d)) {
      DocumentSymbol s =
          symbol(a, l->name.name, "lsystem", SymbolKind::Namespace, l->span, l->name.span);
      s.children = lsystem_items(a, *l);
      out.push_back(std::move(s));
    } else if (const auto* p = std::get_if<ast::Pieces>(&d)) {
      DocumentSymbol s =
          symbol(a, p->name.name, "pieces", SymbolKind::Namespace, p->span, p->name.span);
      for (const ast::PiecesItem& item : p->items) {
        if (const auto* piece = std::get_if<ast::PieceDecl>(&item)) {
          s.children.push_back(symbol(a, piece->name.name, piece->ctor.kind.name, SymbolKind::Class,
                                      piece->span, piece->name.span));
        } else if (const auto* rim = std::get_if<ast::RimDecl>(&item)) {
          s.children.push_back(
              symbol(a, rim->name.name, "rim", SymbolKind::Property, rim->span, rim->name.span));
        }
      }
      out.push_back(std::move(s));
    } else if (const auto* v = std::get_if<ast::Voxels>(&d)) {
      out.push_back(
          symbol(a, v->name.name, "voxels", SymbolKind::Namespace, v->span, v->name.span));
    }
  }
  return out;
}

}  // namespace ramus::lsp
