// Module names as written, and what they stand for (grammar/modules.h, docs/language.md): a
// turtle symbol, a declared name or one character is one module; an undeclared name of several
// letters is one module per letter (`FF` is `F F`); any other undeclared name (`S_1`, `N2`)
// must be declared.
#include "grammar/detail/check_context.h"
#include "grammar/modules.h"

namespace ramus::detail {

bool is_turtle_symbol(std::string_view name) {
  return name.size() == 1 &&
         std::string_view("+-&^\\/|$[]!'~%{.}").find(name[0]) != std::string_view::npos;
}

std::vector<std::string> module_parts(const CheckContext& cx, std::uint32_t file,
                                      std::string_view name) {
  // One character, or declared: the name itself (the common case, one hash lookup at most).
  if (name.size() <= 1 || cx.find_module(file, std::string(name))) return {std::string(name)};
  auto undeclared = [](std::string_view) { return false; };
  if (!splits_into_letters(name, undeclared)) return {};  // `S_1`, `N2`: must be declared
  return split_module_name(name, undeclared);
}

}  // namespace ramus::detail
