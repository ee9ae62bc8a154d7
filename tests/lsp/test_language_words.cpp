// The language words the editor shows (lsp/language_words.h) agree with the front end: every
// setting listed is one the checker accepts, every builtin of grammar/builtins.h has a
// signature with its arity, every turtle symbol the checker knows has a meaning.
#include <catch2/catch.hpp>
#include <string>

#include "grammar/builtins.h"
#include "grammar/check.h"
#include "grammar/loader.h"
#include "lsp/language_words.h"

using namespace ramus;

TEST_CASE("language words: settings are accepted by the checker, unknown ones are not") {
  auto check = [](const std::string& setting) {
    const std::string values = setting == "tropism" ? "0, 0, -1" : "2";
    SourceManager sm;
    DiagnosticSink sink;
    Program p = load_program_text(
        "t.ramus", "lsystem t {\n  " + setting + " " + values + ";\n  axiom F;\n}\n", sm, sink);
    check_program(p, sm, sink);
    return sink.all().empty();
  };
  for (const lsp::Word& w : lsp::lsystem_settings()) {
    INFO(w.name);
    CHECK(check(std::string(w.name)));
  }
  CHECK_FALSE(check("dervie"));  // the test can fail
}

TEST_CASE("language words: every builtin has a signature of its arity") {
  for (const BuiltinInfo& b : kBuiltins) {
    const lsp::Word* w = lsp::find_word(lsp::builtin_functions(), b.name);
    INFO(b.name);
    REQUIRE(w != nullptr);
    const std::string sig(w->signature);
    CHECK(sig.substr(0, b.name.size() + 1) == std::string(b.name) + "(");
    CHECK(std::size_t(std::count(sig.begin(), sig.end(), ',')) == b.arity - 1u);
  }
  CHECK(lsp::builtin_functions().size() == std::size(kBuiltins));
}

TEST_CASE("language words: the turtle symbols of docs/language.md have meanings") {
  for (char c : std::string("+-&^\\/|$[]!'~%Ff")) {
    INFO(c);
    CHECK(lsp::find_word(lsp::turtle_symbols(), std::string(1, c)) != nullptr);
  }
}
