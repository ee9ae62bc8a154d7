#include "lsp/definition.h"

#include "lsp/cursor.h"
#include "lsp/import_path.h"
#include "lsp/module_info.h"
#include "lsp/uri.h"

namespace ramus::lsp {

namespace {

const ast::Identifier* formal_parameter(const ast::Production& p, const std::string& name) {
  for (const auto* seq : {&p.left_context, &p.right_context}) {
    for (const ast::ModulePattern& m : *seq) {
      for (const ast::Identifier& id : m.params) {
        if (id.name == name) return &id;
      }
    }
  }
  for (const ast::Identifier& id : p.predecessor.params) {
    if (id.name == name) return &id;
  }
  return nullptr;
}

}  // namespace

std::vector<Location> definition_at(const Analysis& a, const Position& position) {
  using K = Definition::Kind;
  const ast::File* root = a.root();
  if (root == nullptr) return {};
  CursorTarget t = target_at(*root, a.offset_of(position));
  switch (t.kind) {
    case CursorTarget::Kind::Name: {
      if (t.production) {
        if (const ast::Identifier* id = formal_parameter(*t.production, t.name)) {
          return {a.location(id->span)};
        }
      }
      if (const Definition* d = a.find(t.name, {K::Const, K::Param})) {
        return {a.location(d->name_span)};
      }
      return {};
    }
    case CursorTarget::Kind::Module: {
      if (const Definition* d = a.find(t.name, {K::Module})) return {a.location(d->name_span)};
      std::vector<const ast::Production*> prods = productions_of(a, t.name);
      if (prods.empty()) return {};
      const ast::ModulePattern& p = prods.front()->predecessor;
      SourceSpan name{p.span.file, p.span.begin, p.span.begin + std::uint32_t(p.name.size())};
      return {a.location(name)};
    }
    case CursorTarget::Kind::Import: {
      std::optional<std::string> path = resolve_import(*t.import, a.sources().name(a.root_id()));
      if (!path) return {};
      return {Location{uri_of_path(*path), Range{}}};
    }
    case CursorTarget::Kind::Piece:
    case CursorTarget::Kind::Block:
      if (const Definition* d =
              a.find(t.name, {K::Piece, K::Rim, K::LSystem, K::Pieces, K::Voxels})) {
        return {a.location(d->name_span)};
      }
      return {};
    case CursorTarget::Kind::None:
    case CursorTarget::Kind::Function:
    case CursorTarget::Kind::Setting:
      return {};
  }
  return {};
}

}  // namespace ramus::lsp
