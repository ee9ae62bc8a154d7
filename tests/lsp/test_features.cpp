// The features of the server on an analysed document, in process (lsp/analysis.h and the
// feature headers): what hover says about each kind of name, where definition goes, what
// completion offers, the outline, and diagnostics that come from an imported file.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "lsp/completion.h"
#include "lsp/definition.h"
#include "lsp/diagnostics.h"
#include "lsp/document_symbols.h"
#include "lsp/hover.h"
#include "lsp/uri.h"

namespace {

namespace fs = std::filesystem;
using namespace ramus::lsp;

const std::string kText =
    "param n = 4;  // steps\n"
    "lsystem plant {\n"
    "  derive n;\n"
    "  angle 25.7;\n"
    "  axiom X;\n"
    "  X -> F[+X]F[-X]+X;\n"
    "  F(l) : l > 0 -> F(sqrt(l) * 2)F;\n"
    "}\n";

// The position of the `nth` occurrence of `needle` in kText, plus `shift` characters.
Position at(const std::string& needle, int nth = 0, unsigned shift = 0) {
  std::size_t off = kText.find(needle);
  while (nth-- > 0) off = kText.find(needle, off + 1);
  REQUIRE(off != std::string::npos);
  LineIndex lines(kText, PositionEncoding::Utf16);
  Position p = lines.position(std::uint32_t(off));
  p.character += shift;
  return p;
}

std::string hover_text(const Analysis& a, const Position& p) {
  std::optional<Hover> h = hover_at(a, p);
  return h ? h->markdown : "";
}

}  // namespace

TEST_CASE("features: hover on each kind of name") {
  Analysis a("untitled:plant", "", kText, PositionEncoding::Utf16);
  REQUIRE(a.diagnostics().empty());
  CHECK(hover_text(a, at("n;")).find("param n = 4") != std::string::npos);
  CHECK(hover_text(a, at("n;")).find("steps") != std::string::npos);
  CHECK(hover_text(a, at("derive")).find("derivation steps") != std::string::npos);
  CHECK(hover_text(a, at("+X")).find("turn left") != std::string::npos);
  CHECK(hover_text(a, at("[+X")).find("push") != std::string::npos);
  CHECK(hover_text(a, at("F[")).find("move forward") != std::string::npos);
  CHECK(hover_text(a, at("sqrt")).find("sqrt(x)") != std::string::npos);
  CHECK(hover_text(a, at("l)", 1)).find("parameter of `F(l)`") != std::string::npos);
  // X is not declared: its signature from the productions, and how many rewrite it.
  const std::string x = hover_text(a, at("X ->"));
  CHECK(x.find("```ramus\nX\n```") != std::string::npos);
  CHECK(x.find("1 production rewrites it") != std::string::npos);
  CHECK(hover_text(a, at("plant")).find("lsystem plant {") != std::string::npos);
  CHECK_FALSE(hover_at(a, at("25.7")).has_value());  // a number: nothing to say
}

TEST_CASE(
    "features: definition of parameters, modules without a declaration, nothing for builtins") {
  Analysis a("untitled:plant", "", kText, PositionEncoding::Utf16);
  std::vector<Location> n = definition_at(a, at("n;"));
  REQUIRE(n.size() == 1);
  CHECK(n[0].range.start == Position{0, 6});
  std::vector<Location> x = definition_at(a, at("X;"));  // in the axiom
  REQUIRE(x.size() == 1);
  CHECK(x[0].range.start == at("X ->"));  // the production that rewrites it
  std::vector<Location> l = definition_at(a, at("l)", 1));
  REQUIRE(l.size() == 1);
  CHECK(l[0].range.start == at("l) :"));  // the pattern's parameter
  CHECK(definition_at(a, at("sqrt")).empty());
  CHECK(definition_at(a, at("+X")).empty());
}

TEST_CASE("features: completion in and out of a production, and the outline") {
  Analysis a("untitled:plant", "", kText, PositionEncoding::Utf16);
  auto labels = [](const std::vector<CompletionItem>& items) {
    std::vector<std::string> out;
    for (const CompletionItem& i : items) out.push_back(i.label);
    return out;
  };
  auto count = [](const std::vector<std::string>& v, const std::string& s) {
    return std::count(v.begin(), v.end(), s);
  };
  std::vector<std::string> inside = labels(completion_at(a, at("sqrt")));
  CHECK(count(inside, "l") == 1);
  CHECK(count(inside, "n") == 1);
  CHECK(count(inside, "X") == 1);
  CHECK(count(inside, "F") == 1);  // once, as the turtle symbol
  std::vector<std::string> outside = labels(completion_at(a, at("derive")));
  CHECK(count(outside, "l") == 0);  // no production around the cursor
  CHECK(count(outside, "max_depth") == 1);

  std::vector<DocumentSymbol> symbols = document_symbols(a);
  REQUIRE(symbols.size() == 2);
  CHECK(symbols[0].name == "n");
  CHECK(symbols[0].kind == SymbolKind::Variable);
  CHECK(symbols[1].name == "plant");
  REQUIRE(symbols[1].children.size() == 3);
  CHECK(symbols[1].children[0].name == "axiom");
  CHECK(symbols[1].children[2].name == "F(l)");
  CHECK(symbols[1].children[2].detail == "production : l > 0");
}

TEST_CASE("features: an error in an imported file is shown at the import") {
  fs::path dir = fs::temp_directory_path() / ("ramus_lsp_features_" + std::to_string(getpid()));
  fs::create_directories(dir / "parts");
  std::ofstream(dir / "parts" / "leaf.ramus") << "const size = 1 +;\n";
  const std::string text = "import \"parts/leaf.ramus\";\nlsystem t {\n  axiom F;\n}\n";
  const std::string path = (dir / "main.ramus").string();
  Analysis a(uri_of_path(path), path, text, PositionEncoding::Utf16);
  std::vector<LspDiagnostic> d = document_diagnostics(a);
  REQUIRE(d.size() == 1);
  CHECK(d[0].code == "E0003");
  CHECK(d[0].range.start == Position{0, 0});  // the import
  CHECK(d[0].message.find("leaf.ramus") != std::string::npos);
  REQUIRE(d[0].related.size() == 1);
  CHECK(d[0].related[0].location.uri == uri_of_path((dir / "parts" / "leaf.ramus").string()));
  CHECK(d[0].related[0].location.range.start.line == 0);
  std::vector<Location> def = definition_at(a, {0, 10});
  REQUIRE(def.size() == 1);
  CHECK(def[0].uri == uri_of_path((dir / "parts" / "leaf.ramus").string()));
  fs::remove_all(dir);
}

TEST_CASE("features: after `import`, completion offers the stdlib and the files beside") {
  fs::path dir = fs::temp_directory_path() / ("ramus_lsp_imports_" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "leaf.ramus") << "const size = 1;\n";
  const std::string path = (dir / "main.ramus").string();
  const std::string text = "import t\nlsystem t {\n  axiom F;\n}\n";
  Analysis a(uri_of_path(path), path, text, PositionEncoding::Utf16);
  std::vector<std::string> labels;
  for (const CompletionItem& i : completion_at(a, {0, 8})) labels.push_back(i.label);
  CHECK(std::count(labels.begin(), labels.end(), "abop") == 1);
  CHECK(std::count(labels.begin(), labels.end(), "trees.broadleaf") == 1);
  CHECK(std::count(labels.begin(), labels.end(), "\"leaf.ramus\"") == 1);
  CHECK(std::count(labels.begin(), labels.end(), "axiom") == 0);  // only what may be imported
  std::vector<std::string> elsewhere;
  for (const CompletionItem& i : completion_at(a, {2, 8})) elsewhere.push_back(i.label);
  CHECK(std::count(elsewhere.begin(), elsewhere.end(), "trees.broadleaf") == 0);
  fs::remove_all(dir);
}
