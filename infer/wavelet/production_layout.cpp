// The formatter's layout of one production (production_layout.h).
#include "infer/wavelet/production_layout.h"

namespace ramus::wavelet {
namespace {

constexpr std::size_t kWidth = 100;
constexpr std::size_t kContinuation = 8;

bool is_name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

// Two modules are written together, with a space only where they would otherwise merge.
void append_module(std::string& out, const std::string& text) {
  if (!out.empty() && !text.empty()) {
    const char a = out.back(), b = text.front();
    if ((is_name_char(a) && is_name_char(b)) || (a == '/' && (b == '/' || b == '*'))) out += ' ';
  }
  out += text;
}

}  // namespace

std::string production_layout(const std::string& head, const std::vector<std::string>& modules) {
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
  if (atoms.empty()) return head + ";\n";
  atoms.back() += ";";
  std::string out;
  std::string cur = head + " ";
  std::size_t line_start = 0;
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
    std::string line = line_start == 0 ? head + " " : std::string(kContinuation, ' ');
    for (std::size_t k = line_start; k < at; ++k) {
      if (k == line_start) {
        line += atoms[k];
      } else {
        append_module(line, atoms[k]);
      }
    }
    out += line + "\n";
    cur = std::string(kContinuation, ' ');
    line_start = i = at;
  }
  return out + cur + "\n";
}

}  // namespace ramus::wavelet
