#include "lsp/cursor.h"

#include <optional>

namespace ramus::lsp {

namespace {

using Kind = CursorTarget::Kind;

bool holds(const SourceSpan& s, std::uint32_t offset) {
  return s.begin <= offset && offset < s.end;
}

// A walk of one file that stops at the first (innermost) name holding the offset.
class Finder {
 public:
  explicit Finder(std::uint32_t offset) : offset_(offset) {}

  std::optional<CursorTarget> file(const ast::File& f) {
    for (const ast::Decl& d : f.decls) {
      if (auto t = std::visit([&](const auto& x) { return decl(x); }, d)) return t;
    }
    return std::nullopt;
  }

 private:
  std::optional<CursorTarget> hit(Kind kind, std::string name, SourceSpan span) {
    if (!holds(span, offset_)) return std::nullopt;
    CursorTarget t;
    t.kind = kind;
    t.name = std::move(name);
    t.span = span;
    t.production = production_;
    return t;
  }

  std::optional<CursorTarget> expr(const ast::Expr& e) {
    if (!holds(e.span, offset_)) return std::nullopt;
    if (const auto* n = std::get_if<ast::NameRef>(&e.node)) return hit(Kind::Name, n->name, e.span);
    if (const auto* u = std::get_if<ast::Unary>(&e.node)) return expr(*u->operand);
    if (const auto* b = std::get_if<ast::Binary>(&e.node)) {
      if (auto t = expr(*b->lhs)) return t;
      return expr(*b->rhs);
    }
    if (const auto* c = std::get_if<ast::Conditional>(&e.node)) {
      for (const ast::Expr* x : {&*c->cond, &*c->then_expr, &*c->else_expr}) {
        if (auto t = expr(*x)) return t;
      }
      return std::nullopt;
    }
    if (const auto* c = std::get_if<ast::Call>(&e.node)) {
      if (auto t = hit(Kind::Function, c->callee.name, c->callee.span)) return t;
      return exprs(c->args);
    }
    return std::nullopt;
  }

  std::optional<CursorTarget> exprs(const std::vector<ast::Expr>& es) {
    for (const ast::Expr& e : es) {
      if (auto t = expr(e)) return t;
    }
    return std::nullopt;
  }

  // The name of a module is written first in its span.
  static SourceSpan name_span(const SourceSpan& s, const std::string& name) {
    return {s.file, s.begin, s.begin + std::uint32_t(name.size())};
  }

  std::optional<CursorTarget> pattern(const ast::ModulePattern& p) {
    if (auto t = hit(Kind::Module, p.name, name_span(p.span, p.name))) return t;
    for (const ast::Identifier& id : p.params) {
      if (auto t = hit(Kind::Name, id.name, id.span)) return t;
    }
    return std::nullopt;
  }

  std::optional<CursorTarget> call(const ast::ModuleCall& c) {
    if (auto t = hit(Kind::Module, c.name, name_span(c.span, c.name))) return t;
    return exprs(c.args);
  }

  std::optional<CursorTarget> decl(const ast::Import& im) {
    auto t = hit(Kind::Import, im.path, im.span);
    if (t) t->import = &im;
    return t;
  }

  std::optional<CursorTarget> decl(const ast::ConstDecl& c) {
    for (const ast::Binding& b : c.bindings) {
      if (auto t = hit(Kind::Name, b.name.name, b.name.span)) return t;
      if (auto t = expr(b.value)) return t;
    }
    return std::nullopt;
  }

  std::optional<CursorTarget> decl(const ast::ModuleDecl& m) {
    for (const ast::ModulePattern& p : m.modules) {
      if (auto t = hit(Kind::Module, p.name, name_span(p.span, p.name))) return t;
    }
    return std::nullopt;
  }

  std::optional<CursorTarget> decl(const ast::LSystem& l) {
    if (auto t = hit(Kind::Block, l.name.name, l.name.span)) return t;
    if (!holds(l.span, offset_)) return std::nullopt;
    for (const ast::LSystemItem& item : l.items) {
      if (auto t = std::visit([&](const auto& x) { return this->item(x); }, item)) return t;
    }
    return std::nullopt;
  }

  std::optional<CursorTarget> item(const ast::Setting& s) {
    if (auto t = hit(Kind::Setting, s.key.name, s.key.span)) return t;
    return exprs(s.values);
  }
  std::optional<CursorTarget> item(const ast::Axiom& a) {
    for (const ast::ModuleCall& c : a.modules) {
      if (auto t = call(c)) return t;
    }
    return std::nullopt;
  }
  std::optional<CursorTarget> item(const ast::SymbolSet& s) {
    for (const ast::Identifier& id : s.symbols) {
      if (auto t = hit(Kind::Module, id.name, id.span)) return t;
    }
    return std::nullopt;
  }
  std::optional<CursorTarget> item(const ast::Select& s) { return exprs(s.keys); }
  std::optional<CursorTarget> item(const ast::Production& p) {
    if (!holds(p.span, offset_)) return std::nullopt;
    production_ = &p;
    std::optional<CursorTarget> t = production(p);
    production_ = nullptr;
    return t;
  }
  std::optional<CursorTarget> production(const ast::Production& p) {
    for (const ast::ModulePattern& m : p.left_context) {
      if (auto t = pattern(m)) return t;
    }
    if (auto t = pattern(p.predecessor)) return t;
    for (const ast::ModulePattern& m : p.right_context) {
      if (auto t = pattern(m)) return t;
    }
    if (p.guard) {
      if (auto t = expr(*p.guard)) return t;
    }
    if (auto t = exprs(p.key)) return t;
    for (const ast::Alternative& a : p.alternatives) {
      if (a.probability) {
        if (auto t = expr(*a.probability)) return t;
      }
      for (const ast::ModuleCall& c : a.successor) {
        if (auto t = call(c)) return t;
      }
    }
    return std::nullopt;
  }

  std::optional<CursorTarget> named_args(const std::vector<ast::NamedArg>& args) {
    for (const ast::NamedArg& a : args) {
      if (auto t = expr(a.value)) return t;
    }
    return std::nullopt;
  }

  std::optional<CursorTarget> decl(const ast::Pieces& p) {
    if (auto t = hit(Kind::Block, p.name.name, p.name.span)) return t;
    if (!holds(p.span, offset_)) return std::nullopt;
    for (const ast::PiecesItem& item : p.items) {
      if (const auto* rim = std::get_if<ast::RimDecl>(&item)) {
        if (auto t = hit(Kind::Piece, rim->name.name, rim->name.span)) return t;
        if (auto t = named_args(rim->args)) return t;
      } else if (const auto* piece = std::get_if<ast::PieceDecl>(&item)) {
        if (auto t = hit(Kind::Piece, piece->name.name, piece->name.span)) return t;
        if (auto t = named_args(piece->ctor.args)) return t;
      } else if (const auto* rule = std::get_if<ast::AttachRule>(&item)) {
        if (auto t = hit(Kind::Piece, rule->piece.name, rule->piece.span)) return t;
        if (auto t = hit(Kind::Piece, rule->rim.name, rule->rim.span)) return t;
        for (const ast::WeightedPiece& w : rule->targets) {
          if (auto t = hit(Kind::Piece, w.piece.name, w.piece.span)) return t;
          if (w.weight) {
            if (auto t = expr(*w.weight)) return t;
          }
        }
      } else if (const auto* s = std::get_if<ast::PieceSetting>(&item)) {
        if (auto t = exprs(s->values)) {
          // `root I;` names a piece, not a constant.
          if (s->key.name == "root" && t->kind == Kind::Name) t->kind = Kind::Piece;
          return t;
        }
      }
    }
    return std::nullopt;
  }

  std::optional<CursorTarget> decl(const ast::Voxels& v) {
    if (auto t = hit(Kind::Block, v.name.name, v.name.span)) return t;
    if (!holds(v.span, offset_)) return std::nullopt;
    for (const ast::VoxelsItem& item : v.items) {
      if (const auto* s = std::get_if<ast::VoxelSetting>(&item)) {
        if (auto t = exprs(s->values)) return t;
      } else if (const auto* r = std::get_if<ast::VoxelRule>(&item)) {
        if (auto t = expr(r->parent)) return t;
        if (auto t = exprs(r->children)) return t;
        if (r->weight) {
          if (auto t = expr(*r->weight)) return t;
        }
      }
    }
    return std::nullopt;
  }

  std::uint32_t offset_;
  const ast::Production* production_ = nullptr;
};

}  // namespace

CursorTarget target_at(const ast::File& file, std::uint32_t offset) {
  if (auto t = Finder(offset).file(file)) return *t;
  if (offset > 0) {
    if (auto t = Finder(offset - 1).file(file)) return *t;
  }
  return {};
}

const ast::Production* production_at(const ast::File& file, std::uint32_t offset) {
  for (const ast::Decl& d : file.decls) {
    const auto* l = std::get_if<ast::LSystem>(&d);
    if (l == nullptr || !holds(l->span, offset)) continue;
    for (const ast::LSystemItem& item : l->items) {
      const auto* p = std::get_if<ast::Production>(&item);
      if (p != nullptr && p->span.begin <= offset && offset <= p->span.end) return p;
    }
  }
  return nullptr;
}

}  // namespace ramus::lsp
