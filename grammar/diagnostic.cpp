// Diagnostics: the code table (from diagnostic_codes.def), the sink, and the two renderings
// (text with source line and caret, and JSON for editors and tools).
#include "grammar/diagnostic.h"

#include <algorithm>
#include <cstdio>

namespace ramus {

const std::vector<DiagCodeInfo>& all_diag_codes() {
  static const std::vector<DiagCodeInfo> table = {
#define RAMUS_DIAG(name, code, severity, summary) {DiagCode::name, code, severity, summary},
#include "grammar/diagnostic_codes.def"
#undef RAMUS_DIAG
  };
  return table;
}

const DiagCodeInfo& info(DiagCode code) {
  // The enum is declared from the same list in the same order, so it indexes the table.
  return all_diag_codes()[static_cast<std::size_t>(code)];
}

Diagnostic& DiagnosticSink::report(DiagCode code, SourceSpan span, std::string message) {
  Severity s = info(code).severity;
  if (s == Severity::Error) ++errors_;
  if (s == Severity::Warning) ++warnings_;
  diags_.push_back(Diagnostic{code, s, span, std::move(message), {}});
  return diags_.back();
}

void DiagnosticSink::note(SourceSpan span, std::string message) {
  if (diags_.empty()) return;
  diags_.back().notes.push_back(DiagNote{span, true, std::move(message)});
}

void DiagnosticSink::sort() {
  std::stable_sort(diags_.begin(), diags_.end(), [](const Diagnostic& a, const Diagnostic& b) {
    if (a.span.file != b.span.file) return a.span.file < b.span.file;
    if (a.span.begin != b.span.begin) return a.span.begin < b.span.begin;
    return a.code < b.code;
  });
}

namespace {

const char* severity_name(Severity s) {
  switch (s) {
    case Severity::Error:
      return "error";
    case Severity::Warning:
      return "warning";
    case Severity::Note:
      return "note";
  }
  return "error";
}

bool has_file(const SourceManager& sm, const SourceSpan& span) { return span.file < sm.size(); }

std::string location(const SourceManager& sm, const SourceSpan& span) {
  if (!has_file(sm, span)) return "<input>";
  LineCol lc = sm.line_col(span.file, span.begin);
  return sm.name(span.file) + ":" + std::to_string(lc.line) + ":" + std::to_string(lc.column);
}

// A source line made safe for a terminal: control characters (and, in a line that is not
// UTF-8, every non-ASCII byte) become '?'; tabs stay so the caret line can copy them.
std::string printable(std::string_view line) {
  std::string out(line);
  bool ascii_only = false;
  for (std::size_t i = 0; i < out.size();) {
    unsigned char c = static_cast<unsigned char>(out[i]);
    std::size_t n = c < 0x80 ? 1 : c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC2 ? 2 : 0;
    bool ok = n > 0 && i + n <= out.size();
    for (std::size_t k = 1; ok && k < n; ++k) {
      ok = (static_cast<unsigned char>(out[i + k]) & 0xC0) == 0x80;
    }
    if (!ok) {
      ascii_only = true;
      break;
    }
    i += n;
  }
  for (char& ch : out) {
    unsigned char c = static_cast<unsigned char>(ch);
    if ((c < 0x20 && c != '\t') || c == 0x7F || (ascii_only && c >= 0x80)) ch = '?';
  }
  return out;
}

// The widest piece of a source line a snippet quotes, and how much of it goes before the span.
// One line of garbage (a minified or binary file) can hold thousands of errors, and quoting the
// whole line under each made the output grow with the square of the input: 5,277 errors on one
// 11 KB line wrote 211 MB. A window of a terminal's width around the span keeps it linear.
constexpr std::size_t kSnippetWidth = 120;
constexpr std::size_t kSnippetLead = 40;

bool continuation_byte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

// "  3 | text" and "    |   ^~~~" for a span (clipped to its first line, and a long line to a
// window around the span, marked "..." where it is cut).
void append_snippet(std::string& out, const SourceManager& sm, const SourceSpan& span, bool color) {
  if (!has_file(sm, span) || sm.text(span.file).empty()) return;
  std::uint32_t size = std::uint32_t(sm.text(span.file).size());
  std::uint32_t begin = std::min(span.begin, size);
  LineCol lc = sm.line_col(span.file, begin);
  const std::string_view raw = sm.line_text(span.file, begin);
  const std::size_t col0 = std::min<std::size_t>(lc.column - 1, raw.size());
  std::size_t from = 0, to = raw.size();
  if (raw.size() > kSnippetWidth) {
    from = col0 > kSnippetLead ? col0 - kSnippetLead : 0;
    to = std::min(raw.size(), from + kSnippetWidth);
    while (from > 0 && continuation_byte(raw[from])) --from;  // whole UTF-8 characters
    while (to < raw.size() && continuation_byte(raw[to])) ++to;
  }
  const std::string cut_before = from > 0 ? "..." : "", cut_after = to < raw.size() ? "..." : "";
  std::string line = printable(raw.substr(from, to - from));
  std::string num = std::to_string(lc.line);
  std::size_t width = std::max<std::size_t>(3, num.size());
  out += std::string(width - num.size(), ' ') + num + " | " + cut_before + line + cut_after + "\n";
  std::string pad(cut_before.size(), ' ');
  for (std::size_t i = 0; from + i < col0 && i < line.size(); ++i) {
    pad += line[i] == '\t' ? '\t' : ' ';
  }
  std::size_t rest = to > col0 ? to - col0 : 0;  // up to the end of the quoted piece
  std::size_t len =
      std::max<std::size_t>(1, std::min<std::size_t>(span.end - std::min(span.end, begin), rest));
  std::string caret = "^" + std::string(len - 1, '~');
  if (color) caret = "\033[1;32m" + caret + "\033[0m";
  out += std::string(width, ' ') + " | " + pad + caret + "\n";
}

void append_json_string(std::string& out, std::string_view s) {
  out += '"';
  for (std::size_t i = 0; i < s.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(s[i]);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += char(c);
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c < 0x20 || c == 0x7F) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else if (c < 0x80) {
      out += char(c);
    } else {
      // Copy a well-formed UTF-8 sequence; replace a stray byte with U+FFFD.
      std::size_t n = c >= 0xF0 && c <= 0xF4 ? 4 : c >= 0xE0 ? 3 : c >= 0xC2 && c < 0xE0 ? 2 : 0;
      bool ok = n > 0 && i + n <= s.size();
      for (std::size_t k = 1; ok && k < n; ++k) {
        ok = (static_cast<unsigned char>(s[i + k]) & 0xC0) == 0x80;
      }
      if (ok) {
        out.append(s.substr(i, n));
        i += n - 1;
      } else {
        out += "\\ufffd";
      }
    }
  }
  out += '"';
}

void append_json_position(std::string& out, const SourceManager& sm, const SourceSpan& span) {
  out += "\"file\":";
  append_json_string(out, has_file(sm, span) ? sm.name(span.file) : "<input>");
  LineCol b, e;
  if (has_file(sm, span)) {
    b = sm.line_col(span.file, span.begin);
    e = sm.line_col(span.file, std::max(span.begin, span.end));
  }
  out += ",\"line\":" + std::to_string(b.line) + ",\"column\":" + std::to_string(b.column) +
         ",\"end_line\":" + std::to_string(e.line) + ",\"end_column\":" + std::to_string(e.column);
}

}  // namespace

std::string render_text(const SourceManager& sm, const Diagnostic& d, bool color) {
  const char* sev = severity_name(d.severity);
  std::string head = location(sm, d.span) + ": ";
  std::string kind = std::string(sev) + "[" + info(d.code).id + "]";
  if (color) {
    const char* c = d.severity == Severity::Error     ? "\033[1;31m"
                    : d.severity == Severity::Warning ? "\033[1;35m"
                                                      : "\033[1;36m";
    head = "\033[1m" + head + "\033[0m";
    kind = c + kind + "\033[0m";
  }
  std::string out = head + kind + ": " + d.message + "\n";
  append_snippet(out, sm, d.span, color);
  for (const DiagNote& n : d.notes) {
    if (n.has_span) {
      out += location(sm, n.span) + ": note: " + n.message + "\n";
      append_snippet(out, sm, n.span, color);
    } else {
      out += "note: " + n.message + "\n";
    }
  }
  return out;
}

std::string render_text(const SourceManager& sm, const std::vector<Diagnostic>& ds, bool color) {
  std::string out;
  for (const Diagnostic& d : ds) out += render_text(sm, d, color);
  return out;
}

std::string render_json(const SourceManager& sm, const std::vector<Diagnostic>& ds) {
  std::string out = "{\"diagnostics\":[";
  for (std::size_t i = 0; i < ds.size(); ++i) {
    const Diagnostic& d = ds[i];
    if (i) out += ",";
    out += "{";
    append_json_position(out, sm, d.span);
    out += ",\"severity\":\"" + std::string(severity_name(d.severity)) + "\",\"code\":\"" +
           info(d.code).id + "\",\"message\":";
    append_json_string(out, d.message);
    out += ",\"notes\":[";
    for (std::size_t k = 0; k < d.notes.size(); ++k) {
      if (k) out += ",";
      out += "{";
      if (d.notes[k].has_span) {
        append_json_position(out, sm, d.notes[k].span);
        out += ",";
      }
      out += "\"message\":";
      append_json_string(out, d.notes[k].message);
      out += "}";
    }
    out += "]}";
  }
  out += "]}\n";
  return out;
}

}  // namespace ramus
