// Module names as modules: an identifier of several characters that is not declared with
// `module` (in the file or its imports) stands for one module per letter, as in ABOP and L-Py:
// `FF` is `F F`, and arguments attach to the last letter (`AB(1)` is `A B(1)`). See
// docs/language.md, "Module names".
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace ramus {

// The modules a name written in a module sequence or pattern stands for:
// - a declared name, a single character or a turtle symbol: the name itself;
// - an undeclared name of two or more letters (A-Z, a-z): one single-letter name per letter;
// - anything else (undeclared with digits or '_', such as `S_1` or `N2`): the name unchanged,
//   and the checks report it as an unknown module.
std::vector<std::string> split_module_name(
    std::string_view name, const std::function<bool(std::string_view)>& is_declared);

// True when `name` is split by split_module_name (undeclared, two or more letters only).
bool splits_into_letters(std::string_view name,
                         const std::function<bool(std::string_view)>& is_declared);

// True when `s` is an identifier of the language: a letter or '_', then letters, digits or '_'.
bool is_identifier(std::string_view s);

}  // namespace ramus
