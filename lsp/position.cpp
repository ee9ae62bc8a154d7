#include "lsp/position.h"

#include <algorithm>

namespace ramus::lsp {

namespace {

// The length of the UTF-8 sequence that starts with `lead` (1 for a stray continuation byte,
// so that malformed text still advances).
std::uint32_t sequence_length(unsigned char lead) {
  if (lead >= 0xF0) return 4;
  if (lead >= 0xE0) return 3;
  if (lead >= 0xC0) return 2;
  return 1;
}

// UTF-16 code units of the character whose UTF-8 sequence has `length` bytes.
unsigned utf16_units(std::uint32_t length) { return length == 4 ? 2 : 1; }

}  // namespace

const char* encoding_name(PositionEncoding e) {
  return e == PositionEncoding::Utf8 ? "utf-8" : "utf-16";
}

LineIndex::LineIndex(std::string_view text, PositionEncoding encoding)
    : text_(text), encoding_(encoding), starts_{0} {
  for (std::uint32_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') {
      starts_.push_back(i + 1);
    } else if (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n')) {
      starts_.push_back(i + 1);
    }
  }
}

std::uint32_t LineIndex::line_end(std::size_t line) const {
  std::uint32_t e = line + 1 < starts_.size() ? starts_[line + 1] : std::uint32_t(text_.size());
  std::uint32_t b = starts_[line];
  if (e > b && text_[e - 1] == '\n') --e;
  if (e > b && text_[e - 1] == '\r') --e;
  return e;
}

Position LineIndex::position(std::uint32_t offset) const {
  offset = std::min<std::uint32_t>(offset, std::uint32_t(text_.size()));
  auto it = std::upper_bound(starts_.begin(), starts_.end(), offset);
  std::size_t line = std::size_t(it - starts_.begin()) - 1;
  std::uint32_t b = starts_[line];
  offset = std::min(offset, line_end(line));
  if (encoding_ == PositionEncoding::Utf8) return {unsigned(line), offset - b};
  unsigned units = 0;
  for (std::uint32_t i = b; i < offset;) {
    std::uint32_t n = sequence_length(static_cast<unsigned char>(text_[i]));
    if (i + n > offset) break;  // inside a sequence: the start of its character
    units += utf16_units(n);
    i += n;
  }
  return {unsigned(line), units};
}

std::uint32_t LineIndex::offset(const Position& p) const {
  if (p.line >= starts_.size()) return std::uint32_t(text_.size());
  std::uint32_t b = starts_[p.line], e = line_end(p.line);
  if (encoding_ == PositionEncoding::Utf8) {
    std::uint32_t o = std::min<std::uint32_t>(b + p.character, e);
    // Never inside a UTF-8 sequence: back to the start of its character.
    while (o > b && o < text_.size() && (static_cast<unsigned char>(text_[o]) & 0xC0) == 0x80) --o;
    return o;
  }
  unsigned units = 0;
  std::uint32_t i = b;
  while (i < e && units < p.character) {
    std::uint32_t n = sequence_length(static_cast<unsigned char>(text_[i]));
    if (units + utf16_units(n) > p.character) break;  // between a surrogate pair's halves
    units += utf16_units(n);
    i = std::min(i + n, e);
  }
  return i;
}

Range LineIndex::range(std::uint32_t begin, std::uint32_t end) const {
  return {position(begin), position(std::max(begin, end))};
}

}  // namespace ramus::lsp
