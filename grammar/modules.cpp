#include "grammar/modules.h"

#include <cctype>

namespace ramus {

namespace {
bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
}  // namespace

bool splits_into_letters(std::string_view name,
                         const std::function<bool(std::string_view)>& is_declared) {
  if (name.size() < 2) return false;
  for (char c : name) {
    if (!is_letter(c)) return false;
  }
  return !(is_declared && is_declared(name));
}

std::vector<std::string> split_module_name(
    std::string_view name, const std::function<bool(std::string_view)>& is_declared) {
  if (!splits_into_letters(name, is_declared)) return {std::string(name)};
  std::vector<std::string> out;
  out.reserve(name.size());
  for (char c : name) out.emplace_back(1, c);
  return out;
}

bool is_identifier(std::string_view s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char c : s) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  }
  return true;
}

}  // namespace ramus
