#include "lsp/diagnostics.h"

#include <filesystem>
#include <set>

#include "lsp/import_path.h"

namespace ramus::lsp {

namespace {

namespace fs = std::filesystem;

DiagnosticSeverity severity_of(Severity s) {
  switch (s) {
    case Severity::Error:
      return DiagnosticSeverity::Error;
    case Severity::Warning:
      return DiagnosticSeverity::Warning;
    case Severity::Note:
      return DiagnosticSeverity::Information;
  }
  return DiagnosticSeverity::Error;
}

// The files (SourceManager ids) reachable from program file `index` through its imports.
void reachable(const Program& program, std::uint32_t index, std::set<std::uint32_t>& ids) {
  if (!ids.insert(program.files[index].file_id).second) return;
  for (std::uint32_t next : program.imports[index]) reachable(program, next, ids);
}

// The span of the root's import through which file `id` was loaded (the first that reaches it).
std::optional<SourceSpan> import_reaching(const Analysis& a, std::uint32_t id) {
  const Program& program = a.program();
  const ast::File& root = program.files[0];
  for (std::uint32_t direct : program.imports[0]) {
    std::set<std::uint32_t> ids;
    reachable(program, direct, ids);
    if (!ids.count(id)) continue;
    // The import of the root that loaded file `direct`: resolved again, it names the same file.
    std::error_code ec;
    const fs::path loaded =
        fs::weakly_canonical(a.sources().name(program.files[direct].file_id), ec);
    for (const ast::Decl& d : root.decls) {
      const auto* im = std::get_if<ast::Import>(&d);
      if (im == nullptr) continue;
      std::optional<std::string> path = resolve_import(*im, a.sources().name(a.root_id()));
      if (path && fs::weakly_canonical(*path, ec) == loaded) return im->span;
    }
  }
  return std::nullopt;
}

// A span of no characters (a missing `;` is reported just after the previous token) widened to
// the character there, so that editors have something to underline; not across a line end.
SourceSpan visible(const Analysis& a, SourceSpan span) {
  const std::string& text = a.sources().text(span.file);
  if (span.begin == span.end && span.end < text.size() && text[span.end] != '\n' &&
      text[span.end] != '\r')
    ++span.end;
  return span;
}

}  // namespace

std::vector<LspDiagnostic> document_diagnostics(const Analysis& a) {
  std::vector<LspDiagnostic> out;
  for (const Diagnostic& d : a.diagnostics()) {
    LspDiagnostic l;
    l.severity = severity_of(d.severity);
    l.code = info(d.code).id;
    l.message = d.message;
    if (d.span.file == a.root_id()) {
      l.range = a.range(visible(a, d.span));
    } else {
      std::optional<SourceSpan> at = import_reaching(a, d.span.file);
      if (!at) continue;  // not from this document's imports (cannot happen; never shown wrong)
      l.range = a.range(*at);
      l.message = "in " + a.sources().name(d.span.file) + ": " + d.message;
      l.related.push_back({a.location(d.span), d.message});
    }
    for (const DiagNote& n : d.notes) {
      if (n.has_span) {
        l.related.push_back({a.location(n.span), n.message});
      } else {
        l.message += "\nnote: " + n.message;
      }
    }
    out.push_back(std::move(l));
  }
  return out;
}

}  // namespace ramus::lsp
