// split_module_name: how a name written in a module sequence becomes modules.
#include <catch2/catch.hpp>
#include <set>
#include <string>

#include "grammar/modules.h"

using ramus::split_module_name;
using ramus::splits_into_letters;
using Names = std::vector<std::string>;

TEST_CASE("modules: undeclared multi-letter names split into letters", "[modules]") {
  auto none = [](std::string_view) { return false; };
  CHECK(split_module_name("FF", none) == Names{"F", "F"});
  CHECK(split_module_name("AB", none) == Names{"A", "B"});
  CHECK(split_module_name("Fab", none) == Names{"F", "a", "b"});
  CHECK(splits_into_letters("FF", none));
}

TEST_CASE("modules: declared names and single characters stay whole", "[modules]") {
  std::set<std::string, std::less<>> declared = {"Apex", "FF"};
  auto is_declared = [&](std::string_view n) { return declared.count(n) > 0; };
  CHECK(split_module_name("Apex", is_declared) == Names{"Apex"});
  CHECK(split_module_name("FF", is_declared) == Names{"FF"});
  CHECK(split_module_name("FG", is_declared) == Names{"F", "G"});
  CHECK(split_module_name("F", is_declared) == Names{"F"});
  CHECK(split_module_name("+", is_declared) == Names{"+"});
  CHECK(split_module_name("[", is_declared) == Names{"["});
  CHECK_FALSE(splits_into_letters("Apex", is_declared));
  CHECK_FALSE(splits_into_letters("F", is_declared));
}

TEST_CASE("modules: undeclared names with digits or underscores are returned unchanged",
          "[modules]") {
  auto none = [](std::string_view) { return false; };
  CHECK(split_module_name("S_1", none) == Names{"S_1"});
  CHECK(split_module_name("N2", none) == Names{"N2"});
  CHECK(split_module_name("_a", none) == Names{"_a"});
  CHECK_FALSE(splits_into_letters("N2", none));
  // An empty predicate means nothing is declared.
  CHECK(split_module_name("XY", {}) == Names{"X", "Y"});
}
