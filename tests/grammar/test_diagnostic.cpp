// Diagnostics: the code table, the sink, the text rendering (location, source line, caret,
// notes, a long line in a window) and the JSON rendering (valid, escaped).
#include <catch2/catch.hpp>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

#include "grammar/check.h"
#include "grammar/diagnostic.h"
#include "grammar/loader.h"

using namespace ramus;

TEST_CASE("diagnostic: codes are unique, well formed and indexed by the enum", "[diagnostic]") {
  std::set<std::string> ids;
  for (const DiagCodeInfo& c : all_diag_codes()) {
    std::string id = c.id;
    CHECK(ids.insert(id).second);
    REQUIRE(id.size() == 5);
    CHECK((id[0] == 'E' || id[0] == 'W'));
    CHECK((id[0] == 'E') == (c.severity == Severity::Error));
    CHECK(&info(c.code) == &c);
    std::string summary = c.summary;
    REQUIRE(!summary.empty());
    CHECK(summary.back() != '.');
  }
  CHECK(info(DiagCode::SyntaxError).id == std::string("E0003"));
  CHECK(info(DiagCode::ImportCycle).id == std::string("E0602"));
}

TEST_CASE("diagnostic: the sink counts, attaches notes and sorts", "[diagnostic]") {
  DiagnosticSink sink;
  sink.note({0, 1, 2}, "a note with nothing to attach to is dropped");
  sink.report(DiagCode::UnusedConstant, {0, 20, 21}, "unused constant 'a'");
  sink.report(DiagCode::SyntaxError, {0, 5, 6}, "expected ';'");
  sink.note({0, 1, 2}, "earlier");
  sink.report(DiagCode::NestingTooDeep, {0, 5, 6}, "deep");
  CHECK(sink.error_count() == 2);
  CHECK(sink.warning_count() == 1);
  CHECK(sink.has_errors());
  CHECK(sink.all()[1].notes.size() == 1);
  CHECK(sink.all()[0].notes.empty());
  sink.sort();
  CHECK(sink.all()[0].code == DiagCode::SyntaxError);
  CHECK(sink.all()[1].code == DiagCode::NestingTooDeep);
  CHECK(sink.all()[2].code == DiagCode::UnusedConstant);
}

TEST_CASE("diagnostic: text has location, source line, caret and notes", "[diagnostic]") {
  SourceManager sm;
  std::uint32_t f = sm.add("g.ramus", "const a = 1;\nlsystem x {\n  A -> B Q;\n}\n");
  DiagnosticSink sink;
  // `Q` on line 3
  sink.report(DiagCode::UnknownModule, {f, 34, 35}, "unknown module 'Q'");
  sink.note({f, 0, 5}, "declared modules are listed here");
  std::string text = render_text(sm, sink.all());
  CHECK(text ==
        "g.ramus:3:10: error[E0101]: unknown module 'Q'\n"
        "  3 |   A -> B Q;\n"
        "    |          ^\n"
        "g.ramus:1:1: note: declared modules are listed here\n"
        "  1 | const a = 1;\n"
        "    | ^~~~~\n");
}

TEST_CASE("diagnostic: carets keep tabs, stop at the line end and mark empty spans",
          "[diagnostic]") {
  SourceManager sm;
  std::uint32_t f = sm.add("t.ramus", "\tA -> B\n");
  Diagnostic d{DiagCode::SyntaxError, Severity::Error, {f, 7, 7}, "expected ';'", {}};
  CHECK(render_text(sm, d) ==
        "t.ramus:1:8: error[E0003]: expected ';'\n"
        "  1 | \tA -> B\n"
        "    | \t      ^\n");
  Diagnostic wide{DiagCode::SyntaxError, Severity::Error, {f, 1, 100}, "x", {}};
  CHECK(render_text(sm, wide).find("| \t^~~~~~\n") != std::string::npos);
  // Line numbers wider than the gutter widen it.
  std::string many;
  for (int i = 0; i < 1200; ++i) many += "x\n";
  std::uint32_t g = sm.add("m.ramus", many);
  Diagnostic far{DiagCode::SyntaxError, Severity::Error, {g, 2398, 2399}, "far", {}};
  CHECK(render_text(sm, far) == "m.ramus:1200:1: error[E0003]: far\n1200 | x\n     | ^\n");
}

TEST_CASE("diagnostic: control bytes and broken UTF-8 are not printed raw", "[diagnostic]") {
  SourceManager sm;
  std::uint32_t f = sm.add("b.ramus", std::string("ab\0\x1b[31m\xff", 9));
  Diagnostic d{DiagCode::BinaryInput, Severity::Error, {f, 2, 3}, "not text", {}};
  std::string text = render_text(sm, d);
  CHECK(text.find('\0') == std::string::npos);
  CHECK(text.find('\x1b') == std::string::npos);
  CHECK(text.find('\xff') == std::string::npos);
  CHECK(text.find("  1 | ab??[31m?\n") != std::string::npos);
}

TEST_CASE("diagnostic: a long line is quoted in a window around the span", "[diagnostic]") {
  // One line of garbage can hold thousands of errors; quoting all of it under each one made the
  // output grow with the square of the input (5,277 errors on an 11 KB line wrote 211 MB).
  SourceManager sm;
  std::string line(1000, 'a');
  line.replace(500, 3, "QQQ");
  std::uint32_t f = sm.add("long.ramus", line + "\n");
  Diagnostic d{DiagCode::UnknownModule, Severity::Error, {f, 500, 503}, "unknown", {}};
  const std::string text = render_text(sm, d);
  const std::string quoted =
      "  1 | ..." + std::string(40, 'a') + "QQQ" + std::string(77, 'a') + "...\n";
  CHECK(text == "long.ramus:1:501: error[E0101]: unknown\n" + quoted + "    |    " +
                    std::string(40, ' ') + "^~~\n");
  // Near the start the window starts with the line; a caret runs at most to the window's end.
  Diagnostic first{DiagCode::SyntaxError, Severity::Error, {f, 2, 900}, "x", {}};
  CHECK(render_text(sm, first) == "long.ramus:1:3: error[E0003]: x\n  1 | " +
                                      std::string(120, 'a') + "...\n    |   ^" +
                                      std::string(117, '~') + "\n");
  // The window does not cut a UTF-8 character: 2-byte characters from byte 0, the span at 300.
  std::string wide;
  for (int i = 0; i < 400; ++i) wide += "\xc3\xa9";
  std::uint32_t g = sm.add("wide.ramus", wide + "\n");
  Diagnostic w{DiagCode::SyntaxError, Severity::Error, {g, 301, 302}, "x", {}};
  const std::string wt = render_text(sm, w);
  const std::size_t from = wt.find("| ...") + 5, to = wt.find("...\n", from);
  REQUIRE(to != std::string::npos);
  CHECK((to - from) % 2 == 0);
  CHECK(wt.find('?') == std::string::npos);  // still valid UTF-8, nothing replaced

  // The fuzzer's input: one line of 11,312 bytes with 5,277 errors (211 MB of text before).
  std::ifstream in(RAMUS_SOURCE_DIR "/tests/fuzz/corpus/parse_check/regress_long_line_errors.ramus",
                   std::ios::binary);
  const std::string garbage{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  REQUIRE(garbage.size() == 11312);
  SourceManager gsm;
  DiagnosticSink diags;
  LoadOptions options;
  options.stdlib_dirs = {"/nonexistent-ramus-stdlib"};
  Program program = load_program_text("garbage.ramus", garbage, gsm, diags, options);
  if (!program.files.empty()) check_program(program, gsm, diags);
  REQUIRE(diags.error_count() > 5000);
  // A few lines of a terminal's width for each diagnostic and its note (3.0 MB).
  CHECK(render_text(gsm, diags.all()).size() < 1000 * diags.all().size());
}

TEST_CASE("diagnostic: JSON is one valid document with escaped strings", "[diagnostic]") {
  SourceManager sm;
  std::uint32_t f = sm.add("dir/\"q\".ramus", "A -> B;\n");
  std::vector<Diagnostic> ds;
  ds.push_back({DiagCode::UnknownModule, Severity::Error, {f, 5, 6}, "unknown 'B'\t\\ \x01", {}});
  ds[0].notes.push_back({{f, 0, 1}, true, "here"});
  ds[0].notes.push_back({{}, false, "caf\xC3\xA9 \xff"});
  std::string json = render_json(sm, ds);
  CHECK(json ==
        "{\"diagnostics\":[{\"file\":\"dir/\\\"q\\\".ramus\",\"line\":1,\"column\":6,"
        "\"end_line\":1,\"end_column\":7,\"severity\":\"error\",\"code\":\"E0101\","
        "\"message\":\"unknown 'B'\\t\\\\ \\u0001\",\"notes\":[{\"file\":\"dir/\\\"q\\\".ramus\","
        "\"line\":1,\"column\":1,\"end_line\":1,\"end_column\":2,\"message\":\"here\"},"
        "{\"message\":\"caf\xC3\xA9 \\ufffd\"}]}]}\n");
  CHECK(render_json(sm, {}) == "{\"diagnostics\":[]}\n");
}
