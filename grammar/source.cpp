#include "grammar/source.h"

#include <algorithm>

namespace ramus {

std::uint32_t SourceManager::add(std::string name, std::string text) {
  File f{std::move(name), std::move(text), {0}};
  for (std::uint32_t i = 0; i < f.text.size(); ++i) {
    if (f.text[i] == '\n') f.line_starts.push_back(i + 1);
  }
  files_.push_back(std::move(f));
  return std::uint32_t(files_.size() - 1);
}

std::string_view SourceManager::slice(const SourceSpan& span) const {
  const std::string& t = files_[span.file].text;
  std::uint32_t b = std::min<std::uint32_t>(span.begin, std::uint32_t(t.size()));
  std::uint32_t e = std::min<std::uint32_t>(std::max(span.end, b), std::uint32_t(t.size()));
  return std::string_view(t).substr(b, e - b);
}

LineCol SourceManager::line_col(std::uint32_t file, std::uint32_t offset) const {
  const auto& starts = files_[file].line_starts;
  auto it = std::upper_bound(starts.begin(), starts.end(), offset);
  std::uint32_t line = std::uint32_t(it - starts.begin());  // 1-based because starts[0] == 0
  return {line, offset - starts[line - 1] + 1};
}

std::string_view SourceManager::line_text(std::uint32_t file, std::uint32_t offset) const {
  const File& f = files_[file];
  offset = std::min<std::uint32_t>(offset, std::uint32_t(f.text.size()));
  std::uint32_t line = line_col(file, offset).line;
  std::uint32_t b = f.line_starts[line - 1];
  std::uint32_t e = line < f.line_starts.size() ? f.line_starts[line] : std::uint32_t(f.text.size());
  while (e > b && (f.text[e - 1] == '\n' || f.text[e - 1] == '\r')) --e;
  return std::string_view(f.text).substr(b, e - b);
}

}  // namespace ramus
