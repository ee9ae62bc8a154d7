// editors/vscode: the extension's JSON files parse, the manifest starts `ramus lsp` for .ramus
// files, and the TextMate grammar highlights every keyword the parser knows (the kw("...")
// words of grammar/detail/rules_def.h), every setting and every builtin function.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>

#include "grammar/builtins.h"
#include "lsp/language_words.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kVscode = fs::path(RAMUS_SOURCE_DIR) / "editors" / "vscode";

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

json read_json(const fs::path& p) {
  INFO(p.string());
  REQUIRE(fs::exists(p));
  return json::parse(slurp(p));  // throws (fails the test) on invalid JSON
}

struct Rule {
  std::regex re;
  std::string scope;  // the rule's name and its captures' names
};

void collect(const json& node, std::vector<Rule>& out) {
  if (node.is_object()) {
    if (node.contains("match")) {
      std::string scope = node.value("name", "");
      if (node.contains("captures")) {
        for (const auto& [k, v] : node["captures"].items()) scope += " " + v.value("name", "");
      }
      out.push_back({std::regex(node["match"].get<std::string>()), scope});
    }
    for (const auto& [k, v] : node.items()) collect(v, out);
  } else if (node.is_array()) {
    for (const json& v : node) collect(v, out);
  }
}

// The scope of the rule that highlights `word` at the start of `sample` as a whole ("" if none).
std::string scope_of(const std::vector<Rule>& rules, const std::string& word,
                     const std::string& sample) {
  for (const Rule& r : rules) {
    std::smatch m;
    if (std::regex_search(sample, m, r.re, std::regex_constants::match_continuous) &&
        m.position(0) == 0 && std::size_t(m.length(0)) >= word.size())
      return r.scope;
  }
  return "";
}

// The keywords the parser matches: kw("word") in its rules.
std::set<std::string> parser_keywords() {
  const std::string rules = slurp(fs::path(RAMUS_SOURCE_DIR) / "grammar/detail/rules_def.h");
  std::set<std::string> out;
  std::regex kw(R"re(kw\("([A-Za-z_]+)"\))re");
  for (auto it = std::sregex_iterator(rules.begin(), rules.end(), kw); it != std::sregex_iterator();
       ++it)
    out.insert((*it)[1]);
  return out;
}

}  // namespace

TEST_CASE("editors: the VS Code manifest starts ramus lsp for .ramus files") {
  json pkg = read_json(kVscode / "package.json");
  CHECK(pkg["main"] == "./extension.js");
  const json& lang = pkg["contributes"]["languages"][0];
  CHECK(lang["id"] == "ramus");
  CHECK(lang["extensions"][0] == ".ramus");
  read_json(kVscode / lang["configuration"].get<std::string>());
  const json& grammar = pkg["contributes"]["grammars"][0];
  CHECK(grammar["scopeName"] == "source.ramus");
  json tm = read_json(kVscode / grammar["path"].get<std::string>());
  CHECK(tm["scopeName"] == "source.ramus");
  CHECK(pkg["dependencies"].contains("vscode-languageclient"));
  const std::string js = slurp(kVscode / "extension.js");
  CHECK(js.find("args: [\"lsp\"]") != std::string::npos);
  CHECK(js.find("vscode-languageclient/node") != std::string::npos);
}

TEST_CASE("editors: the TextMate grammar highlights the parser's keywords, settings and builtins") {
  std::vector<Rule> rules;
  collect(read_json(kVscode / "syntaxes/ramus.tmLanguage.json")["repository"], rules);
  REQUIRE(rules.size() > 5);
  std::set<std::string> words = parser_keywords();
  REQUIRE(words.size() >= 15);  // the test reads the parser: it can fail
  for (const std::string& w : words) {
    INFO(w);
    std::string scope = scope_of(rules, w, w + " x;");
    if (w == "true" || w == "false") scope = scope_of(rules, w, w + ";");
    CHECK((scope.find("keyword") != std::string::npos ||
           scope.find("constant.language") != std::string::npos));
  }
  for (const ramus::lsp::Word& s : ramus::lsp::lsystem_settings()) {
    INFO(s.name);
    CHECK(scope_of(rules, std::string(s.name), std::string(s.name) + " 2;").find("setting") !=
          std::string::npos);
  }
  for (const ramus::BuiltinInfo& b : ramus::kBuiltins) {
    INFO(b.name);
    CHECK(scope_of(rules, std::string(b.name), std::string(b.name) + "(x)")
              .find("support.function") != std::string::npos);
  }
  // Not everything is a keyword: a module name is not.
  CHECK(scope_of(rules, "Apex", "Apex(1)").find("keyword") == std::string::npos);
  CHECK(scope_of(rules, "Apex", "Apex(1)").find("module") != std::string::npos);
}
