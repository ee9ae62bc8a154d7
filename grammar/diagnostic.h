// Diagnostics: what the front end (and any later stage that points into source) reports.
//
// Library code never prints or exits; it appends Diagnostics to a DiagnosticSink and the CLI
// renders them, as text:
//   file:line:col: error[E0101]: unknown module 'Q'
//      3 |   A -> B Q;
//        |          ^
//   note: ...
// or as JSON (--diagnostics=json). Codes are listed once, in grammar/diagnostic_codes.def.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "grammar/source.h"

namespace ramus {

enum class Severity { Error, Warning, Note };

enum class DiagCode : std::uint16_t {
#define RAMUS_DIAG(name, code, severity, summary) name,
#include "grammar/diagnostic_codes.def"
#undef RAMUS_DIAG
};

struct DiagCodeInfo {
  DiagCode code;
  const char* id;       // "E0101"
  Severity severity;
  const char* summary;  // one line, lower case, what the code means
};
const DiagCodeInfo& info(DiagCode code);
const std::vector<DiagCodeInfo>& all_diag_codes();

struct DiagNote {
  SourceSpan span;
  bool has_span = false;
  std::string message;
};

struct Diagnostic {
  DiagCode code;
  Severity severity;
  SourceSpan span;
  std::string message;
  std::vector<DiagNote> notes;
};

class DiagnosticSink {
 public:
  Diagnostic& report(DiagCode code, SourceSpan span, std::string message);
  void note(SourceSpan span, std::string message);  // adds a note to the last diagnostic

  const std::vector<Diagnostic>& all() const { return diags_; }
  bool has_errors() const { return errors_ > 0; }
  std::size_t error_count() const { return errors_; }
  std::size_t warning_count() const { return warnings_; }
  // Stable order for output: by file, then position, then code.
  void sort();

 private:
  std::vector<Diagnostic> diags_;
  std::size_t errors_ = 0;
  std::size_t warnings_ = 0;
};

std::string render_text(const SourceManager& sm, const Diagnostic& d, bool color = false);
std::string render_text(const SourceManager& sm, const std::vector<Diagnostic>& ds,
                        bool color = false);
// One JSON document: {"diagnostics":[{"file":..,"line":..,"column":..,"end_line":..,
// "end_column":..,"severity":..,"code":..,"message":..,"notes":[..]}]}
std::string render_json(const SourceManager& sm, const std::vector<Diagnostic>& ds);

}  // namespace ramus
