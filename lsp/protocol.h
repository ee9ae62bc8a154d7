// The LSP 3.17 message types the server answers with, as plain structs: the features fill them
// and protocol_json.cpp writes them as JSON. Positions and ranges are already in the encoding
// negotiated with the client (position.h); the features work in byte offsets until then.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace ramus::lsp {

struct Position {
  unsigned line = 0;       // 0-based
  unsigned character = 0;  // 0-based, in code units of the negotiated encoding
  bool operator==(const Position&) const = default;
};

struct Range {
  Position start, end;
  bool operator==(const Range&) const = default;
};

struct Location {
  std::string uri;
  Range range;
};

// DiagnosticSeverity of the specification.
enum class DiagnosticSeverity { Error = 1, Warning = 2, Information = 3, Hint = 4 };

struct RelatedInformation {
  Location location;
  std::string message;
};

struct LspDiagnostic {
  Range range;
  DiagnosticSeverity severity = DiagnosticSeverity::Error;
  std::string code;  // "E0101"
  std::string message;
  std::vector<RelatedInformation> related;
};

struct TextEdit {
  Range range;
  std::string new_text;
};

struct Hover {
  std::string markdown;
  Range range;
};

// CompletionItemKind of the specification (the values used here).
enum class CompletionKind {
  Function = 3,
  Variable = 6,
  Class = 7,
  Module = 9,
  Property = 10,
  Keyword = 14,
  Snippet = 15,
  File = 17,
  Constant = 21,
  Operator = 24,
};

struct CompletionItem {
  std::string label;
  CompletionKind kind = CompletionKind::Keyword;
  std::string detail;         // a signature or a value
  std::string documentation;  // markdown
};

// SymbolKind of the specification (the values used here).
enum class SymbolKind {
  File = 1,
  Module = 2,
  Namespace = 3,
  Class = 5,
  Property = 7,
  Function = 12,
  Variable = 13,
  Constant = 14,
  Struct = 23,
};

struct DocumentSymbol {
  std::string name;
  std::string detail;
  SymbolKind kind = SymbolKind::Variable;
  Range range;            // the whole declaration
  Range selection_range;  // its name
  std::vector<DocumentSymbol> children;
};

}  // namespace ramus::lsp
