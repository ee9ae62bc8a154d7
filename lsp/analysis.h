// One open document, analysed: its text loaded with its imports (grammar/loader.h; the open
// text stands in for the file on disk), checked, its constants folded, and an index of the
// names the program declares. The features (hover, definition, completion, symbols) read it; it
// is rebuilt on every change of the document.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "grammar/ast.h"
#include "grammar/diagnostic.h"
#include "grammar/loader.h"
#include "grammar/source.h"
#include "lsp/position.h"
#include "lsp/protocol.h"

namespace ramus::lsp {

// A name declared at file level or in a block, with where it is written.
struct Definition {
  enum class Kind { Const, Param, Module, LSystem, Pieces, Voxels, Piece, Rim };
  Kind kind;
  std::string name;
  SourceSpan name_span;
  SourceSpan decl_span;                         // the whole declaration
  const ast::Expr* value = nullptr;             // Const, Param
  const ast::ModulePattern* pattern = nullptr;  // Module: `A(l, w)` as declared
};

class Analysis {
 public:
  // `uri` names the document; `path` (empty for a document without a file) is the base for
  // relative imports.
  Analysis(std::string uri, const std::string& path, std::string text, PositionEncoding encoding);
  Analysis(const Analysis&) = delete;
  Analysis& operator=(const Analysis&) = delete;

  const std::string& uri() const { return uri_; }
  const SourceManager& sources() const { return sources_; }
  const Program& program() const { return program_; }
  // The root file (the document), or nullptr when it could not be parsed at all.
  const ast::File* root() const { return program_.files.empty() ? nullptr : &program_.files[0]; }
  std::uint32_t root_id() const { return root_id_; }
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }
  PositionEncoding encoding() const { return encoding_; }

  // The folded value of a const or param, when it has one.
  std::optional<double> value_of(const std::string& name) const;
  // Every definition, in file order: the root file's first, then the imports'.
  const std::vector<Definition>& definitions() const { return definitions_; }
  // The first definition of `name` among those of the given kinds (all kinds when empty).
  const Definition* find(const std::string& name,
                         std::initializer_list<Definition::Kind> kinds = {}) const;
  // The comment written with a declaration: the block of `//` lines right above it and the
  // comment after it on its last line; "" when there is none.
  std::string comment_of(const SourceSpan& decl) const;

  // Spans in LSP terms, in the negotiated encoding. Files other than the document get the
  // `file://` URI of their path.
  Range range(const SourceSpan& span) const;
  Location location(const SourceSpan& span) const;
  std::string uri_of_file(std::uint32_t file) const;
  std::uint32_t offset_of(const Position& p) const;  // in the document

 private:
  void index_file(const ast::File& file);
  const LineIndex& lines(std::uint32_t file) const;

  std::string uri_;
  PositionEncoding encoding_;
  SourceManager sources_;
  Program program_;
  std::uint32_t root_id_ = 0;
  std::vector<Diagnostic> diagnostics_;
  std::unordered_map<std::string, double> values_;
  std::vector<Definition> definitions_;
  std::map<std::uint32_t, const ast::File*> file_of_id_;
  mutable std::map<std::uint32_t, std::unique_ptr<LineIndex>> lines_;
};

}  // namespace ramus::lsp
