// The line layout of a module sequence (format.h, `wrap_modules`): the one rule for `ramus fmt`
// and for inference that writes productions in that layout without parsing them again.
#include <cstddef>

#include "grammar/detail/format_parts.h"
#include "grammar/format.h"

namespace ramus {

using detail::append_module;

namespace {

constexpr std::size_t kWidth = 100;
constexpr std::size_t kContinuation = 8;

// The text of atoms [from, to) on one line: the prefix on the first line, else the indent.
std::string line_text(const std::string& prefix, const std::vector<std::string>& atoms,
                      std::size_t from, std::size_t to) {
  std::string s = from == 0 ? prefix + " " : std::string(kContinuation, ' ');
  for (std::size_t k = from; k < to; ++k) {
    if (k == from) {
      s += atoms[k];
    } else {
      append_module(s, atoms[k]);
    }
  }
  return s;
}

}  // namespace

std::string wrap_modules(const std::string& prefix, const std::vector<std::string>& modules,
                         const std::string& suffix) {
  // Atoms: `[` joins the module after it, `]` the module before it.
  std::vector<std::string> atoms;
  bool join_next = false;
  for (const std::string& m : modules) {
    if (!atoms.empty() && (join_next || m == "]")) {
      append_module(atoms.back(), m);
    } else {
      atoms.push_back(m);
    }
    join_next = m == "[";
  }
  if (atoms.empty()) return prefix + suffix + "\n";
  atoms.back() += suffix;
  std::string out;
  std::string cur = prefix + " ";
  std::size_t line_start = 0;  // index of the first atom on the current line
  std::size_t i = 0;
  while (i < atoms.size()) {
    std::string next = cur;
    if (i == line_start) {
      next += atoms[i];
    } else {
      append_module(next, atoms[i]);
    }
    if (i == line_start || next.size() <= kWidth) {
      cur = std::move(next);
      ++i;
      continue;
    }
    // Too long: break before the last `[` on this line, else before this atom.
    std::size_t at = i;
    for (std::size_t k = i; k > line_start; --k) {
      if (atoms[k][0] == '[') {
        at = k;
        break;
      }
    }
    out += line_text(prefix, atoms, line_start, at) + "\n";
    cur = std::string(kContinuation, ' ');
    line_start = i = at;
  }
  return out + cur + "\n";
}

}  // namespace ramus
