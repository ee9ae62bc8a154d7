// Fuzz target for the formatter: any bytes that parse without errors must format to text that
// parses without errors to an equal AST, keeps every comment, and formats to itself again
// (docs/formatting.md). A violation aborts, so the replay of the corpus fails.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "grammar/format.h"
#include "grammar/parser.h"

namespace {

std::vector<std::string> comment_texts(const ramus::ast::File& f) {
  std::vector<std::string> out;
  for (const ramus::ast::Comment& c : f.comments) {
    std::string t = c.text;
    while (!t.empty() && (t.back() == ' ' || t.back() == '\t' || t.back() == '\r')) t.pop_back();
    out.push_back(t);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ramus::SourceManager sm;
  ramus::DiagnosticSink diags;
  std::string text(reinterpret_cast<const char*>(data), size);
  ramus::ast::File file = ramus::parse(sm, sm.add("fuzz.ramus", text), diags);
  if (diags.has_errors()) return 0;  // `ramus fmt` leaves such files alone
  std::string once = ramus::format_file(file, sm);
  ramus::DiagnosticSink again_diags;
  ramus::ast::File again = ramus::parse(sm, sm.add("fuzz.ramus", once), again_diags);
  if (again_diags.has_errors() || !(again == file)) std::abort();
  if (comment_texts(again) != comment_texts(file)) std::abort();
  if (ramus::format_file(again, sm) != once) std::abort();
  return 0;
}
