#include "lsp/analysis.h"

#include <algorithm>
#include <filesystem>

#include "grammar/check.h"
#include "grammar/program_constants.h"
#include "lsp/uri.h"

namespace ramus::lsp {

Analysis::Analysis(std::string uri, const std::string& path, std::string text,
                   PositionEncoding encoding)
    : uri_(std::move(uri)), encoding_(encoding) {
  DiagnosticSink sink;
  // The loader resolves relative imports against the name; a document without a file gets its
  // URI as a name, and then only stdlib imports resolve.
  program_ = load_program_text(path.empty() ? uri_ : path, std::move(text), sources_, sink);
  if (!program_.files.empty()) {
    root_id_ = program_.files[0].file_id;
    check_program(program_, sources_, sink);
    values_ = program_constants(program_, {});
  }
  sink.sort();
  diagnostics_ = sink.all();
  for (const ast::File& f : program_.files) {
    file_of_id_[f.file_id] = &f;
    index_file(f);
  }
}

void Analysis::index_file(const ast::File& file) {
  using K = Definition::Kind;
  for (const ast::Decl& d : file.decls) {
    if (const auto* c = std::get_if<ast::ConstDecl>(&d)) {
      for (const ast::Binding& b : c->bindings) {
        definitions_.push_back(
            {c->is_param ? K::Param : K::Const, b.name.name, b.name.span, c->span, &b.value});
      }
    } else if (const auto* m = std::get_if<ast::ModuleDecl>(&d)) {
      for (const ast::ModulePattern& p : m->modules) {
        SourceSpan name{p.span.file, p.span.begin, p.span.begin + std::uint32_t(p.name.size())};
        definitions_.push_back({K::Module, p.name, name, m->span, nullptr, &p});
      }
    } else if (const auto* l = std::get_if<ast::LSystem>(&d)) {
      definitions_.push_back({K::LSystem, l->name.name, l->name.span, l->span});
    } else if (const auto* p = std::get_if<ast::Pieces>(&d)) {
      definitions_.push_back({K::Pieces, p->name.name, p->name.span, p->span});
      for (const ast::PiecesItem& item : p->items) {
        if (const auto* piece = std::get_if<ast::PieceDecl>(&item)) {
          definitions_.push_back({K::Piece, piece->name.name, piece->name.span, piece->span});
        } else if (const auto* rim = std::get_if<ast::RimDecl>(&item)) {
          definitions_.push_back({K::Rim, rim->name.name, rim->name.span, rim->span});
        }
      }
    } else if (const auto* v = std::get_if<ast::Voxels>(&d)) {
      definitions_.push_back({K::Voxels, v->name.name, v->name.span, v->span});
    }
  }
}

std::optional<double> Analysis::value_of(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

const Definition* Analysis::find(const std::string& name,
                                 std::initializer_list<Definition::Kind> kinds) const {
  for (const Definition& d : definitions_) {
    if (d.name != name) continue;
    if (kinds.size() == 0 || std::find(kinds.begin(), kinds.end(), d.kind) != kinds.end())
      return &d;
  }
  return nullptr;
}

std::string Analysis::comment_of(const SourceSpan& decl) const {
  auto it = file_of_id_.find(decl.file);
  if (it == file_of_id_.end()) return {};
  const std::vector<ast::Comment>& comments = it->second->comments;
  const std::string& text = sources_.text(decl.file);
  const std::uint32_t first_line = sources_.line_col(decl.file, decl.begin).line;
  const std::uint32_t last_line =
      sources_.line_col(decl.file, decl.end > decl.begin ? decl.end - 1 : decl.begin).line;
  // The comments that end on the lines right above the declaration, each alone on its line.
  std::vector<const ast::Comment*> above;
  std::uint32_t want = first_line;
  for (auto c = comments.rbegin(); c != comments.rend(); ++c) {
    if (c->span.end > decl.begin) continue;
    std::uint32_t end_line = sources_.line_col(decl.file, c->span.end - 1).line;
    if (end_line + 1 != want) break;
    LineCol start = sources_.line_col(decl.file, c->span.begin);
    std::string_view before =
        sources_.line_text(decl.file, c->span.begin).substr(0, start.column - 1);
    if (before.find_first_not_of(" \t") != std::string_view::npos) break;  // trails other code
    above.push_back(&*c);
    want = start.line;
  }
  auto strip = [](std::string_view c) {
    if (c.substr(0, 2) == "//")
      c.remove_prefix(2);
    else if (c.substr(0, 2) == "/*")
      c = c.substr(2, c.size() >= 4 ? c.size() - 4 : 0);
    while (!c.empty() && c.front() == ' ') c.remove_prefix(1);
    return std::string(c);
  };
  std::string out;
  for (auto c = above.rbegin(); c != above.rend(); ++c) {
    out += (out.empty() ? "" : "\n") + strip((*c)->text);
  }
  for (const ast::Comment& c : comments) {  // after the declaration, on its last line
    if (c.span.begin < decl.end) continue;
    if (sources_.line_col(decl.file, c.span.begin).line != last_line) break;
    std::string_view between(text.data() + decl.end, c.span.begin - decl.end);
    if (between.find_first_not_of(" \t;") != std::string_view::npos) break;
    out += (out.empty() ? "" : "\n") + strip(c.text);
    break;
  }
  return out;
}

const LineIndex& Analysis::lines(std::uint32_t file) const {
  auto& slot = lines_[file];
  if (!slot) slot = std::make_unique<LineIndex>(sources_.text(file), encoding_);
  return *slot;
}

Range Analysis::range(const SourceSpan& span) const {
  if (span.file >= sources_.size()) return {};
  return lines(span.file).range(span.begin, span.end);
}

std::string Analysis::uri_of_file(std::uint32_t file) const {
  if (file == root_id_) return uri_;
  std::error_code ec;
  std::filesystem::path p = std::filesystem::absolute(sources_.name(file), ec);
  return uri_of_path(ec ? sources_.name(file) : p.lexically_normal().string());
}

Location Analysis::location(const SourceSpan& span) const {
  return {uri_of_file(span.file), range(span)};
}

std::uint32_t Analysis::offset_of(const Position& p) const {
  if (sources_.size() == 0) return 0;
  return lines(root_id_).offset(p);
}

}  // namespace ramus::lsp
