#include "grammar/detail/scan.h"

#include <algorithm>

namespace ramus::detail {

namespace {

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}
bool is_ident_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

// Length of the well-formed UTF-8 sequence at p (RFC 3629: no overlongs, no surrogates, at most
// U+10FFFF), or 0 when the bytes there are not one.
std::size_t utf8_length(std::string_view t, std::size_t p) {
  auto byte = [&](std::size_t i) { return static_cast<unsigned char>(t[i]); };
  unsigned char c = byte(p);
  if (c < 0x80) return 1;
  std::size_t n = 0;
  unsigned char lo = 0x80, hi = 0xBF;  // allowed range of the second byte
  if (c >= 0xC2 && c <= 0xDF) {
    n = 2;
  } else if (c >= 0xE0 && c <= 0xEF) {
    n = 3;
    if (c == 0xE0) lo = 0xA0;
    if (c == 0xED) hi = 0x9F;
  } else if (c >= 0xF0 && c <= 0xF4) {
    n = 4;
    if (c == 0xF0) lo = 0x90;
    if (c == 0xF4) hi = 0x8F;
  } else {
    return 0;
  }
  if (p + n > t.size()) return 0;
  if (byte(p + 1) < lo || byte(p + 1) > hi) return 0;
  for (std::size_t i = 2; i < n; ++i) {
    if (byte(p + i) < 0x80 || byte(p + i) > 0xBF) return 0;
  }
  return n;
}

// Skips a string literal starting at the `"` at p; returns the offset after it (strings end at
// a line break when unterminated; the parser reports that).
std::size_t skip_string(std::string_view t, std::size_t p) {
  ++p;
  while (p < t.size() && t[p] != '"' && t[p] != '\n') {
    p += (t[p] == '\\' && p + 1 < t.size() && t[p + 1] != '\n') ? 2 : 1;
  }
  return p < t.size() && t[p] == '"' ? p + 1 : p;
}

// If a comment starts at p, returns the offset after it (and whether it is terminated).
std::optional<std::size_t> skip_comment(std::string_view t, std::size_t p, bool* terminated) {
  if (p + 1 >= t.size() || t[p] != '/') return std::nullopt;
  if (t[p + 1] == '/') {
    std::size_t e = t.find('\n', p);
    return e == std::string_view::npos ? t.size() : e;
  }
  if (t[p + 1] == '*') {
    std::size_t e = t.find("*/", p + 2);
    if (terminated) *terminated = e != std::string_view::npos;
    return e == std::string_view::npos ? t.size() : e + 2;
  }
  return std::nullopt;
}

}  // namespace

const char* skip_trivia(const char* p, const char* end) {
  std::string_view t(p, std::size_t(end - p));
  return p + skip_trivia(t, 0);
}

std::size_t skip_trivia(std::string_view t, std::size_t p) {
  while (p < t.size()) {
    if (is_space(t[p])) {
      ++p;
    } else if (auto e = skip_comment(t, p, nullptr)) {
      p = *e;
    } else {
      break;
    }
  }
  return p;
}

ScanResult prescan(std::string_view t, std::uint32_t file) {
  ScanResult r;
  for (std::size_t p = 0; p < t.size();) {
    if (t[p] == '\0') {
      r.bad_byte = p;
      return r;
    }
    std::size_t n = utf8_length(t, p);
    if (n == 0) {
      r.bad_byte = p;
      return r;
    }
    p += n;
  }
  if (t.size() >= 3 && t.substr(0, 3) == "\xEF\xBB\xBF") r.start = 3;
  // Braces nest across declarations; `[` never outlives a `;` or a brace, so its depth restarts
  // there (an unbalanced `[` in one production does not count against the next). Parentheses
  // are left to the parser, whose expression depth guard reports them and recovers.
  int braces = 0, inner = 0;
  for (std::size_t p = r.start; p < t.size();) {
    char c = t[p];
    bool terminated = true;
    if (auto e = skip_comment(t, p, &terminated)) {
      r.comments.push_back({std::string(t.substr(p, *e - p)),
                            SourceSpan{file, std::uint32_t(p), std::uint32_t(*e)}});
      if (!terminated && !r.unterminated_comment) r.unterminated_comment = p;
      p = *e;
      continue;
    }
    if (c == '"') {
      p = skip_string(t, p);
      continue;
    }
    if (c == '{') {
      ++braces;
      inner = 0;
    } else if (c == '}') {
      braces = braces > 0 ? braces - 1 : 0;
      inner = 0;
    } else if (c == ';') {
      inner = 0;
    } else if (c == '[') {
      ++inner;
    } else if (c == ']') {
      inner = inner > 0 ? inner - 1 : 0;
    }
    if (braces + inner > kMaxNesting && !r.too_deep) r.too_deep = p;
    ++p;
  }
  return r;
}

// Where a comment or string literal starting at p ends; nullopt when none starts there. Error
// recovery must not stop at a `;` or `}` inside either.
static std::optional<std::size_t> skip_comment_or_string(std::string_view t, std::size_t p) {
  if (auto e = skip_comment(t, p, nullptr)) return e;
  if (t[p] == '"') return skip_string(t, p);
  return std::nullopt;
}

std::size_t recover_in_block(std::string_view t, std::size_t p) {
  int depth = 0;  // ( and [ opened after p
  int braces = 0;
  while (p < t.size()) {
    if (auto e = skip_comment_or_string(t, p)) {
      p = *e;
      continue;
    }
    char c = t[p];
    if (c == '(' || c == '[') {
      ++depth;
    } else if ((c == ')' || c == ']') && depth > 0) {
      --depth;
    } else if (c == '{') {
      ++braces;
    } else if (c == '}') {
      if (braces == 0) return p;  // the block's own closing brace
      --braces;
    } else if (c == ';' && depth == 0 && braces == 0) {
      return p + 1;
    }
    ++p;
  }
  return p;
}

// True when a declaration keyword starts the line at p (only blanks before it on its line).
static bool declaration_starts_line(std::string_view t, std::size_t p) {
  static const std::string_view kWords[] = {"import",  "const",  "param", "module",
                                            "lsystem", "pieces", "voxels"};
  for (std::size_t q = p; q > 0; --q) {
    char c = t[q - 1];
    if (c == '\n') break;
    if (c != ' ' && c != '\t') return false;
  }
  for (std::string_view w : kWords) {
    if (t.substr(p, w.size()) == w &&
        (p + w.size() == t.size() || !is_ident_char(t[p + w.size()]))) {
      return true;
    }
  }
  return false;
}

std::size_t end_of_previous_token(std::string_view t, std::size_t p) {
  p = std::min(p, t.size());
  while (p > 0 && is_space(t[p - 1])) --p;
  return p;
}

std::size_t recover_at_file_level(std::string_view t, std::size_t p) {
  int braces = 0;
  while (p < t.size()) {
    if (braces == 0 && declaration_starts_line(t, p)) return p;
    if (auto e = skip_comment_or_string(t, p)) {
      p = *e;
      continue;
    }
    char c = t[p];
    if (c == '{') {
      ++braces;
    } else if (c == '}') {
      if (braces <= 1) return p + 1;
      --braces;
    } else if (c == ';' && braces == 0) {
      return p + 1;
    }
    ++p;
  }
  return p;
}

std::size_t token_length(std::string_view t, std::size_t p) {
  if (p >= t.size() || t[p] == '\n' || t[p] == '\r') return 0;
  std::size_t e = p;
  while (e < t.size() && is_ident_char(t[e])) ++e;
  if (e > p) return e - p;
  std::size_t n = utf8_length(t, p);
  return n == 0 ? 1 : n;
}

}  // namespace ramus::detail
