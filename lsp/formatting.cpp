#include "lsp/formatting.h"

#include "grammar/format.h"
#include "grammar/parser.h"

namespace ramus::lsp {

std::variant<std::vector<TextEdit>, FormatFailure> format_document(const std::string& name,
                                                                   const std::string& text,
                                                                   PositionEncoding encoding) {
  SourceManager sources;
  DiagnosticSink sink;
  ast::File file = parse(sources, sources.add(name, text), sink);
  if (sink.has_errors()) {
    return FormatFailure{"ramus fmt: " + name + " has syntax errors; left unchanged"};
  }
  std::string result = format_file(file, sources);
  // As `ramus fmt` does: the layout must never change what the file means.
  DiagnosticSink again_sink;
  ast::File again = parse(sources, sources.add(name, result), again_sink);
  if (again_sink.has_errors() || !(again == file)) {
    return FormatFailure{"ramus fmt: internal error: formatting would change the meaning"};
  }
  if (result == text) return std::vector<TextEdit>{};
  LineIndex lines(text, encoding);
  return std::vector<TextEdit>{{lines.range(0, std::uint32_t(text.size())), result}};
}

}  // namespace ramus::lsp
