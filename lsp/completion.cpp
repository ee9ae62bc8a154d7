#include "lsp/completion.h"

#include <algorithm>
#include <filesystem>
#include <optional>

#include "core/number_text.h"
#include "grammar/format.h"
#include "grammar/loader.h"
#include "grammar/modules.h"
#include "lsp/cursor.h"
#include "lsp/language_words.h"
#include "lsp/module_info.h"

namespace ramus::lsp {

namespace {

namespace fs = std::filesystem;

// After `import` on the cursor's line, only what may be imported makes sense: the standard
// library's modules (`trees.broadleaf`) and the .ramus files beside the document (quoted).
std::optional<std::vector<CompletionItem>> import_items(const Analysis& a,
                                                        const Position& position) {
  const std::string& text = a.sources().text(a.root_id());
  const std::size_t end = std::min<std::size_t>(a.offset_of(position), text.size());
  std::size_t begin = end;
  while (begin > 0 && text[begin - 1] != '\n' && text[begin - 1] != '\r') --begin;
  const std::string_view before = std::string_view(text).substr(begin, end - begin);
  std::size_t first = before.find_first_not_of(" \t");
  if (first == std::string_view::npos || before.substr(first, 7) != "import " ||
      before.find(';') != std::string_view::npos)
    return std::nullopt;
  std::vector<CompletionItem> items;
  constexpr std::size_t kMost = 500;  // a stdlib in a huge folder must not stall the editor
  std::error_code ec;
  for (const std::string& dir : default_stdlib_dirs()) {
    for (auto it = fs::recursive_directory_iterator(dir, ec);
         !ec && it != fs::end(it) && items.size() < kMost; it.increment(ec)) {
      if (it->path().extension() != ".ramus") continue;
      std::string name = fs::relative(it->path(), dir, ec).replace_extension().generic_string();
      std::replace(name.begin(), name.end(), '/', '.');
      items.push_back({name, CompletionKind::Module, "standard library", ""});
    }
  }
  const std::string& self = a.sources().name(a.root_id());
  if (fs::path folder = fs::path(self).parent_path(); !folder.empty()) {
    for (auto it = fs::directory_iterator(folder, ec);
         !ec && it != fs::end(it) && items.size() < kMost; it.increment(ec)) {
      if (it->path().extension() != ".ramus" || fs::equivalent(it->path(), self, ec)) continue;
      items.push_back(
          {"\"" + it->path().filename().string() + "\"", CompletionKind::File, "file", ""});
    }
  }
  return items;
}

}  // namespace

std::vector<CompletionItem> completion_at(const Analysis& a, const Position& position) {
  using K = Definition::Kind;
  if (std::optional<std::vector<CompletionItem>> imports = import_items(a, position))
    return *imports;
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
