// An editor's session with `ramus lsp` over stdio, as the acceptance of issue 20 lists it:
// initialize, didOpen of a broken file (diagnostics appear), didChange fixing it (they vanish),
// hover on a param (its value), definition (the `param` line), completion (the params and
// modules in scope), formatting (equal to `ramus fmt`), shutdown and exit.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "lsp/uri.h"
#include "tests/lsp/lsp_session.h"

namespace {

namespace fs = std::filesystem;
using lsp_test::json;
using lsp_test::LspSession;

const char* kBroken =
    "// The branching angle of the tree.\n"
    "param angle_deg = 30;  // degrees\n"
    "const r = 0.5 * 1.5;\n"
    "module Apex(l);\n"
    "\n"
    "lsystem tree {\n"
    "  derive 3;\n"
    "  axiom Apex(1);\n"
    "  Apex(l) -> F(l)[+(angle_deg)Apex(l * r)]Apex(l * r)\n"  // missing ';'
    "}\n";

std::string fixed_text() {
  std::string t = kBroken;
  t.replace(t.find("Apex(l * r)\n}"), 12, "Apex(l * r);\n");
  return t;
}

fs::path scratch(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("ramus_lsp_" + std::to_string(getpid()));
  fs::create_directories(dir);
  return dir / name;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

json position(int line, int character) { return {{"line", line}, {"character", character}}; }

json doc(const std::string& uri) { return {{"uri", uri}}; }

void initialize(LspSession& s) {
  s.request(1, "initialize",
            {{"processId", nullptr}, {"rootUri", nullptr}, {"capabilities", json::object()}});
  json r = s.response(1);
  REQUIRE(r.contains("result"));
  CHECK(r["result"]["capabilities"]["positionEncoding"] == "utf-16");
  CHECK(r["result"]["capabilities"]["hoverProvider"] == true);
  s.notify("initialized");
}

std::vector<std::string> labels(const json& items) {
  std::vector<std::string> out;
  for (const json& i : items) out.push_back(i["label"]);
  return out;
}

bool has(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

}  // namespace

TEST_CASE("lsp session: diagnostics, hover, definition, completion, formatting, shutdown") {
  const fs::path file = scratch("tree.ramus");
  std::ofstream(file) << kBroken;
  const std::string uri = ramus::lsp::uri_of_path(file.string());

  LspSession s;
  initialize(s);
  s.notify("textDocument/didOpen",
           {{"textDocument",
             {{"uri", uri}, {"languageId", "ramus"}, {"version", 1}, {"text", kBroken}}}});
  json diags = s.diagnostics(uri);
  // The syntax error (and, since the production did not parse, a warning that `r` is unused).
  auto syntax =
      std::find_if(diags.begin(), diags.end(), [](const json& d) { return d["code"] == "E0003"; });
  REQUIRE(syntax != diags.end());
  CHECK((*syntax)["severity"] == 1);
  CHECK((*syntax)["source"] == "ramus");
  CHECK((*syntax)["message"].get<std::string>().find("expected ';'") != std::string::npos);
  CHECK((*syntax)["range"]["start"]["line"].get<int>() >= 8);  // at or after the production

  s.notify("textDocument/didChange", {{"textDocument", {{"uri", uri}, {"version", 2}}},
                                      {"contentChanges", {{{"text", fixed_text()}}}}});
  CHECK(s.diagnostics(uri).empty());

  // Hover on `angle_deg` in the successor (line 8): its declaration, value and comment.
  const int line = 8;
  const int col =
      int(std::string(kBroken).substr(std::string(kBroken).find("  Apex(l) ->")).find("angle_deg"));
  s.request(2, "textDocument/hover",
            {{"textDocument", doc(uri)}, {"position", position(line, col + 2)}});
  json hover = s.response(2)["result"];
  REQUIRE(hover.is_object());
  const std::string text = hover["contents"]["value"];
  CHECK(text.find("param angle_deg = 30") != std::string::npos);
  CHECK(text.find("The branching angle of the tree.") != std::string::npos);
  CHECK(text.find("degrees") != std::string::npos);
  CHECK(hover["range"] == json{{"start", position(line, col)}, {"end", position(line, col + 9)}});

  // Hover on the const `r`: its folded value.
  const int r_col = int(std::string("  Apex(l) -> F(l)[+(angle_deg)Apex(l * ").size());
  s.request(3, "textDocument/hover",
            {{"textDocument", doc(uri)}, {"position", position(line, r_col)}});
  const std::string r_text = s.response(3)["result"]["contents"]["value"];
  CHECK(r_text.find("const r = 0.5 * 1.5") != std::string::npos);
  CHECK(r_text.find("value: `0.75`") != std::string::npos);

  // Hover on the module Apex: its declaration.
  s.request(13, "textDocument/hover",
            {{"textDocument", doc(uri)}, {"position", position(line, 3)}});
  const std::string apex = s.response(13)["result"]["contents"]["value"];
  CHECK(apex.find("module Apex(l)") != std::string::npos);
  CHECK(apex.find("1 production rewrites it") != std::string::npos);

  // Definition of `angle_deg`: the `param` line (1), at the name.
  s.request(4, "textDocument/definition",
            {{"textDocument", doc(uri)}, {"position", position(line, col)}});
  json def = s.response(4)["result"];
  REQUIRE(def.size() == 1);
  CHECK(def[0]["uri"] == uri);
  CHECK(def[0]["range"]["start"] == position(1, 6));
  // Definition of the module Apex: its `module` declaration (line 3).
  s.request(5, "textDocument/definition",
            {{"textDocument", doc(uri)}, {"position", position(line, 3)}});
  json mdef = s.response(5)["result"];
  REQUIRE(mdef.size() == 1);
  CHECK(mdef[0]["range"]["start"] == position(3, 7));

  // Completion inside the production: its formal parameter, the param, the const, the module.
  s.request(6, "textDocument/completion",
            {{"textDocument", doc(uri)}, {"position", position(line, col)}});
  std::vector<std::string> items = labels(s.response(6)["result"]);
  for (const char* want :
       {"l", "angle_deg", "r", "Apex", "sin", "uniform", "F", "+", "derive", "axiom"}) {
    INFO(want);
    CHECK(has(items, want));
  }

  // Formatting: the edit turns the text into what `ramus fmt` writes.
  const std::string messy =
      "param  angle_deg=30;\nlsystem tree { axiom F;\n  F -> F[+(angle_deg)F]F; }\n";
  s.notify("textDocument/didChange", {{"textDocument", {{"uri", uri}, {"version", 3}}},
                                      {"contentChanges", {{{"text", messy}}}}});
  s.request(7, "textDocument/formatting",
            {{"textDocument", doc(uri)}, {"options", {{"tabSize", 2}, {"insertSpaces", true}}}});
  json edits = s.response(7)["result"];
  REQUIRE(edits.size() == 1);
  CHECK(edits[0]["range"]["start"] == position(0, 0));
  CHECK(edits[0]["range"]["end"] == position(3, 0));
  const fs::path copy = scratch("messy.ramus");
  std::ofstream(copy) << messy;
  REQUIRE(std::system(("'" + std::string(RAMUS_EXE) + "' fmt '" + copy.string() + "' 2>/dev/null")
                          .c_str()) == 0);
  CHECK(edits[0]["newText"] == slurp(copy));

  // Document symbols: the param and the lsystem with its production.
  s.request(8, "textDocument/documentSymbol", {{"textDocument", doc(uri)}});
  json symbols = s.response(8)["result"];
  REQUIRE(symbols.size() == 2);
  CHECK(symbols[0]["name"] == "angle_deg");
  CHECK(symbols[1]["name"] == "tree");
  CHECK(symbols[1]["children"][1]["name"] == "F");

  s.request(9, "shutdown", nullptr);
  CHECK(s.response(9)["result"].is_null());
  s.notify("exit");
  CHECK(s.wait_exit() == 0);
  fs::remove_all(file.parent_path());
}

TEST_CASE("lsp session: an imported param, its file and related notes") {
  const fs::path example = fs::path(RAMUS_SOURCE_DIR) / "examples/trees/broadleaf.ramus";
  const std::string uri = ramus::lsp::uri_of_path(example.string());
  const std::string text = slurp(example);
  LspSession s;
  initialize(s);
  s.notify(
      "textDocument/didOpen",
      {{"textDocument", {{"uri", uri}, {"languageId", "ramus"}, {"version", 1}, {"text", text}}}});
  CHECK(s.diagnostics(uri).empty());
  // `trunk_width` in the axiom is a param of stdlib/trees/broadleaf.ramus.
  std::istringstream lines(text);
  int line = 0, col = -1;
  for (std::string l; std::getline(lines, l); ++line) {
    if (l.find("axiom") != std::string::npos) {
      col = int(l.find("trunk_width"));
      break;
    }
  }
  REQUIRE(col > 0);
  s.request(2, "textDocument/definition",
            {{"textDocument", doc(uri)}, {"position", position(line, col)}});
  json def = s.response(2)["result"];
  REQUIRE(def.size() == 1);
  CHECK(def[0]["uri"].get<std::string>().find("stdlib/trees/broadleaf.ramus") != std::string::npos);
  s.request(3, "textDocument/hover",
            {{"textDocument", doc(uri)}, {"position", position(line, col)}});
  CHECK(s.response(3)["result"]["contents"]["value"].get<std::string>().find(
            "param trunk_width = 0.5") != std::string::npos);
  // `import abop;` goes to the stdlib file.
  s.request(4, "textDocument/definition",
            {{"textDocument", doc(uri)}, {"position", position(2, 8)}});
  json file_def = s.response(4)["result"];
  REQUIRE(file_def.size() == 1);
  CHECK(file_def[0]["uri"].get<std::string>().find("stdlib/abop.ramus") != std::string::npos);

  // A duplicate definition: the note at the first one becomes relatedInformation.
  s.notify("textDocument/didChange",
           {{"textDocument", {{"uri", uri}, {"version", 2}}},
            {"contentChanges",
             {{{"text", "const a = 1;\nconst a = 2;\nlsystem t {\n  axiom F(a);\n}\n"}}}}});
  json diags = s.diagnostics(uri);
  REQUIRE(diags.size() == 1);
  CHECK(diags[0]["code"] == "E0103");
  CHECK(diags[0]["range"]["start"] == position(1, 6));
  REQUIRE(diags[0]["relatedInformation"].size() == 1);
  CHECK(diags[0]["relatedInformation"][0]["location"]["uri"] == uri);
  CHECK(diags[0]["relatedInformation"][0]["location"]["range"]["start"] == position(0, 6));
  CHECK(diags[0]["relatedInformation"][0]["message"] == "first defined here");
  s.request(5, "shutdown", nullptr);
  s.response(5);
  s.notify("exit");
  CHECK(s.wait_exit() == 0);
}

TEST_CASE("lsp session: utf-8 positions when the client offers them") {
  LspSession s;
  s.request(1, "initialize",
            {{"capabilities", {{"general", {{"positionEncodings", {"utf-8", "utf-16"}}}}}}});
  CHECK(s.response(1)["result"]["capabilities"]["positionEncoding"] == "utf-8");
  s.notify("initialized");
  // "é" is two bytes: in UTF-8 the name after it starts two columns later than in UTF-16.
  const std::string text = "/* é */ param p = 2;\nlsystem t {\n  axiom F(p);\n}\n";
  s.notify("textDocument/didOpen",
           {{"textDocument",
             {{"uri", "untitled:a"}, {"languageId", "ramus"}, {"version", 1}, {"text", text}}}});
  s.diagnostics("untitled:a");
  s.request(2, "textDocument/definition",
            {{"textDocument", doc("untitled:a")}, {"position", position(2, 10)}});
  json def = s.response(2)["result"];
  REQUIRE(def.size() == 1);
  CHECK(def[0]["range"]["start"] == position(0, 15));
  s.notify("exit");
  CHECK(s.wait_exit() == 1);  // exit without shutdown
}

TEST_CASE("lsp session: saving an imported file analyses the documents that import it again") {
  const fs::path main = scratch("main.ramus"), part = scratch("part.ramus");
  std::ofstream(part) << "param size = 2;\n";
  const std::string main_text = "import \"part.ramus\";\nlsystem t {\n  axiom F(size);\n}\n";
  std::ofstream(main) << main_text;
  const std::string main_uri = ramus::lsp::uri_of_path(main.string());
  const std::string part_uri = ramus::lsp::uri_of_path(part.string());
  LspSession s;
  initialize(s);
  s.notify("textDocument/didOpen",
           {{"textDocument",
             {{"uri", main_uri}, {"languageId", "ramus"}, {"version", 1}, {"text", main_text}}}});
  CHECK(s.diagnostics(main_uri).empty());
  // Hover on the declared-in-import param, then break the import on disk and save it.
  s.request(2, "textDocument/hover",
            {{"textDocument", doc(main_uri)}, {"position", position(2, 11)}});
  CHECK(s.response(2)["result"]["contents"]["value"].get<std::string>().find("param size = 2") !=
        std::string::npos);
  std::ofstream(part) << "param size = ;\n";
  s.notify("textDocument/didOpen", {{"textDocument",
                                     {{"uri", part_uri},
                                      {"languageId", "ramus"},
                                      {"version", 1},
                                      {"text", "param size = ;\n"}}}});
  CHECK_FALSE(s.diagnostics(part_uri).empty());
  s.notify("textDocument/didSave", {{"textDocument", doc(part_uri)}});
  json diags = s.diagnostics(main_uri);
  // The syntax error of part.ramus at the import (and `size` is now unknown in main.ramus).
  auto at_import = std::find_if(diags.begin(), diags.end(), [](const json& d) {
    return d["range"]["start"] == position(0, 0) && d["code"] == "E0003";
  });
  REQUIRE(at_import != diags.end());
  CHECK((*at_import)["relatedInformation"][0]["location"]["uri"] == part_uri);
  s.request(3, "shutdown", nullptr);
  s.response(3);
  s.notify("exit");
  CHECK(s.wait_exit() == 0);
}
