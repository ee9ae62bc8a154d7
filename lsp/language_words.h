// The words of the .ramus language an editor shows: the turtle symbols with their meaning, the
// builtin functions with their signatures, the lsystem settings and the keywords
// (docs/language.md: "Keywords", "Settings", "Turtle"). Hover and completion read them; a test
// checks them against the checker (every setting here is accepted, every builtin of
// grammar/builtins.h has a signature here).
#pragma once

#include <span>
#include <string_view>

namespace ramus::lsp {

struct Word {
  std::string_view name;
  std::string_view signature;  // how it is written with its arguments
  std::string_view meaning;    // one sentence, markdown
};

std::span<const Word> turtle_symbols();
std::span<const Word> builtin_functions();  // the non-random and the random ones
std::span<const Word> lsystem_settings();
// The keywords: at the start of a declaration, at the start of a block item, as expressions.
std::span<const Word> keywords();

// The entry of `name` in `words`, or nullptr.
const Word* find_word(std::span<const Word> words, std::string_view name);

}  // namespace ramus::lsp
