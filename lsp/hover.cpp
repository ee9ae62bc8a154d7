#include "lsp/hover.h"

#include "core/number_text.h"
#include "grammar/builtins.h"
#include "grammar/format.h"
#include "grammar/modules.h"
#include "lsp/cursor.h"
#include "lsp/import_path.h"
#include "lsp/language_words.h"
#include "lsp/module_info.h"

namespace ramus::lsp {

namespace {

std::string code(const std::string& s) { return "```ramus\n" + s + "\n```"; }

void paragraph(std::string& out, const std::string& text) {
  if (text.empty()) return;
  out += (out.empty() ? "" : "\n\n") + text;
}

std::string where(const Analysis& a, const SourceSpan& span) {
  if (span.file == a.root_id()) return {};
  return "from `" + a.sources().name(span.file) + "`";
}

// A formal parameter of the production around the cursor: `l` in `A(l, w) -> F(l)`.
const ast::ModulePattern* binder(const ast::Production& p, const std::string& name) {
  auto binds = [&](const ast::ModulePattern& m) {
    for (const ast::Identifier& id : m.params) {
      if (id.name == name) return true;
    }
    return false;
  };
  if (binds(p.predecessor)) return &p.predecessor;
  for (const auto* seq : {&p.left_context, &p.right_context}) {
    for (const ast::ModulePattern& m : *seq) {
      if (binds(m)) return &m;
    }
  }
  return nullptr;
}

std::string constant_hover(const Analysis& a, const Definition& d) {
  std::string decl = (d.kind == Definition::Kind::Param ? "param " : "const ") + d.name + " = " +
                     format_expr(*d.value);
  std::string out = code(decl);
  if (std::optional<double> v = a.value_of(d.name)) {
    std::string text = shortest_text(*v);
    if (text != format_expr(*d.value)) paragraph(out, "value: `" + text + "`");
  }
  paragraph(out, a.comment_of(d.decl_span));
  if (d.kind == Definition::Kind::Param) paragraph(out, "override with `-D " + d.name + "=VALUE`");
  paragraph(out, where(a, d.name_span));
  return out;
}

std::string module_hover(const Analysis& a, const std::string& name) {
  std::string out;
  const Definition* d = a.find(name, {Definition::Kind::Module});
  std::vector<const ast::Production*> prods = productions_of(a, name);
  const Word* turtle = d ? nullptr : find_word(turtle_symbols(), name);
  if (turtle) {
    out = code(std::string(turtle->signature));
    paragraph(out, "turtle: " + std::string(turtle->meaning));
  } else {
    out = code((d ? "module " : "") + module_signature(a, name));
    if (d) {
      paragraph(out, a.comment_of(d->decl_span));
      paragraph(out, where(a, d->name_span));
    }
  }
  if (!d && !turtle) {
    auto declared = [&](std::string_view n) {
      return a.find(std::string(n), {Definition::Kind::Module}) != nullptr;
    };
    std::vector<std::string> parts = split_module_name(name, declared);
    if (parts.size() > 1) {
      std::string list;
      for (const std::string& p : parts) list += (list.empty() ? "" : " ") + p;
      paragraph(out, "an undeclared name of several letters: the modules `" + list + "`");
    }
  }
  if (!prods.empty()) {
    std::string n = std::to_string(prods.size());
    paragraph(out, n + (prods.size() == 1 ? " production rewrites it" : " productions rewrite it"));
  }
  return out;
}

}  // namespace

std::optional<Hover> hover_at(const Analysis& a, const Position& position) {
  const ast::File* root = a.root();
  if (root == nullptr) return std::nullopt;
  CursorTarget t = target_at(*root, a.offset_of(position));
  std::string md;
  switch (t.kind) {
    case CursorTarget::Kind::None:
      return std::nullopt;
    case CursorTarget::Kind::Name: {
      if (t.production) {
        if (const ast::ModulePattern* m = binder(*t.production, t.name)) {
          md = code(t.name) + "\n\nparameter of `" + pattern_text(*m) + "`";
          break;
        }
      }
      if (const Definition* d =
              a.find(t.name, {Definition::Kind::Const, Definition::Kind::Param})) {
        md = constant_hover(a, *d);
      } else if (double v; find_named_constant(t.name, v)) {
        md = code(t.name) + "\n\nnamed constant: `" + shortest_text(v) + "`";
      } else {
        return std::nullopt;
      }
      break;
    }
    case CursorTarget::Kind::Module:
      md = module_hover(a, t.name);
      break;
    case CursorTarget::Kind::Function: {
      const Word* w = find_word(builtin_functions(), t.name);
      if (w == nullptr) return std::nullopt;
      md = code(std::string(w->signature)) + "\n\n" + std::string(w->meaning);
      break;
    }
    case CursorTarget::Kind::Setting: {
      const Word* w = find_word(lsystem_settings(), t.name);
      if (w == nullptr) return std::nullopt;
      md = code(std::string(w->signature)) + "\n\n" + std::string(w->meaning);
      break;
    }
    case CursorTarget::Kind::Import: {
      std::optional<std::string> path = resolve_import(*t.import, a.sources().name(a.root_id()));
      md = code("import " + std::string(t.import->is_file ? "\"" + t.name + "\"" : t.name));
      paragraph(md, path ? "reads `" + *path + "`" : "not found");
      break;
    }
    case CursorTarget::Kind::Piece:
    case CursorTarget::Kind::Block: {
      const Definition* d =
          a.find(t.name, {Definition::Kind::Piece, Definition::Kind::Rim, Definition::Kind::LSystem,
                          Definition::Kind::Pieces, Definition::Kind::Voxels});
      if (d == nullptr) return std::nullopt;
      std::string_view first = a.sources().line_text(d->decl_span.file, d->decl_span.begin);
      md = code(std::string(first));
      paragraph(md, a.comment_of(d->decl_span));
      break;
    }
  }
  return Hover{md, a.range(t.span)};
}

}  // namespace ramus::lsp
