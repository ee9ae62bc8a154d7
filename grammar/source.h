// Source files and positions. Every AST node carries a SourceSpan; the SourceManager turns one
// into file:line:col and the text of the line for diagnostics.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ramus {

// Byte offsets [begin, end) into the file with index `file` in the SourceManager.
struct SourceSpan {
  std::uint32_t file = 0;
  std::uint32_t begin = 0;
  std::uint32_t end = 0;
  bool operator==(const SourceSpan&) const = default;
};

struct LineCol {
  std::uint32_t line = 1;    // 1-based
  std::uint32_t column = 1;  // 1-based, in bytes
};

class SourceManager {
 public:
  // Adds a file's text; returns its index. `name` is what diagnostics print.
  std::uint32_t add(std::string name, std::string text);

  std::size_t size() const { return files_.size(); }
  const std::string& name(std::uint32_t file) const { return files_[file].name; }
  const std::string& text(std::uint32_t file) const { return files_[file].text; }
  std::string_view slice(const SourceSpan& span) const;

  LineCol line_col(std::uint32_t file, std::uint32_t offset) const;
  // The text of the line holding `offset`, without its line terminator.
  std::string_view line_text(std::uint32_t file, std::uint32_t offset) const;

 private:
  struct File {
    std::string name;
    std::string text;
    std::vector<std::uint32_t> line_starts;
  };
  std::vector<File> files_;
};

}  // namespace ramus
