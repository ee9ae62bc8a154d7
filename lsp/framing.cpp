#include "lsp/framing.h"

#include <cctype>
#include <charconv>

namespace ramus::lsp {

namespace {

// Header names are case-insensitive (they follow HTTP's).
bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) !=
        std::tolower(static_cast<unsigned char>(b[i])))
      return false;
  }
  return true;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

}  // namespace

FrameReader::FrameReader(ReadFn read, std::size_t max_body)
    : read_(std::move(read)), max_body_(max_body) {}

bool FrameReader::fill() {
  // Drop what has been read, so that a long session of pipelined messages does not grow the
  // buffer: only the unread tail (a partial message) is kept.
  if (pos_ > 0) {
    buffer_.erase(0, pos_);
    pos_ = 0;
  }
  char chunk[65536];
  std::size_t n = read_(chunk, sizeof chunk);
  if (n == 0) return false;
  buffer_.append(chunk, n);
  return true;
}

std::optional<std::string> FrameReader::line() {
  for (;;) {
    std::size_t nl = buffer_.find('\n', pos_);
    if (nl != std::string::npos) {
      std::string out = buffer_.substr(pos_, nl - pos_);
      pos_ = nl + 1;
      if (!out.empty() && out.back() == '\r') out.pop_back();
      return out;
    }
    // A header line longer than any real one: the stream is not LSP; drop it piecewise.
    if (buffer_.size() - pos_ > 8192) {
      pos_ = buffer_.size();
      return std::string("\x01");  // a line no header matches
    }
    if (!fill()) return std::nullopt;
  }
}

bool FrameReader::read_exact(std::size_t n, std::string& out) {
  while (buffer_.size() - pos_ < n) {
    if (!fill()) return false;
  }
  out.assign(buffer_, pos_, n);
  pos_ += n;
  return true;
}

Frame FrameReader::next() {
  std::optional<std::size_t> length;
  std::string error;
  bool any = false;
  for (;;) {
    std::optional<std::string> l = line();
    if (!l) return {};
    if (l->empty()) {
      if (!any) continue;  // blank lines between messages are tolerated
      break;
    }
    any = true;
    std::string_view s = *l;
    std::size_t colon = s.find(':');
    if (colon == std::string_view::npos) {
      error = "header line without ':'";
      continue;
    }
    std::string_view name = trim(s.substr(0, colon)), value = trim(s.substr(colon + 1));
    if (!iequals(name, "Content-Length")) continue;  // Content-Type and others: not needed
    std::size_t n = 0;
    auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
    if (ec != std::errc() || end != value.data() + value.size()) {
      error = "Content-Length is not a number: '" + std::string(value) + "'";
      continue;
    }
    length = n;
  }
  if (!error.empty() || !length) {
    return {Frame::Kind::BadHeader, {}, error.empty() ? "no Content-Length header" : error};
  }
  if (*length > max_body_) {
    std::string skipped;
    std::size_t left = *length;
    while (left > 0) {  // skip in pieces, never holding the whole body
      std::size_t n = std::min<std::size_t>(left, 1 << 20);
      if (!read_exact(n, skipped)) return {};
      left -= n;
    }
    return {Frame::Kind::BadHeader,
            {},
            "message of " + std::to_string(*length) + " bytes is over the limit"};
  }
  Frame f{Frame::Kind::Message, {}, {}};
  if (!read_exact(*length, f.body)) return {};
  return f;
}

std::string frame_message(std::string_view json) {
  std::string out = "Content-Length: " + std::to_string(json.size()) + "\r\n\r\n";
  out += json;
  return out;
}

}  // namespace ramus::lsp
