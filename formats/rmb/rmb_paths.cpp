#include "formats/rmb/rmb_paths.h"

#include <filesystem>
#include <map>
#include <system_error>

namespace ramus {

namespace {

namespace fs = std::filesystem;

fs::path canonical_or_empty(const fs::path& p) {
  std::error_code ec;
  if (!fs::exists(p, ec)) return {};
  fs::path c = fs::weakly_canonical(p, ec);
  return ec ? fs::path() : c;
}

// `inner` relative to `dir` when it lies inside it (no ".." step), else empty.
fs::path inside(const fs::path& inner, const fs::path& dir) {
  if (dir.empty()) return {};
  fs::path rel = inner.lexically_relative(dir);
  if (rel.empty() || *rel.begin() == "..") return {};
  return rel;
}

}  // namespace

std::string portable_source_name(const std::string& file, const std::string& root_file,
                                 const std::vector<std::string>& stdlib_dirs) {
  const fs::path canon = canonical_or_empty(file);
  if (canon.empty()) return file;
  for (const std::string& dir : stdlib_dirs) {
    const fs::path rel = inside(canon, canonical_or_empty(dir));
    if (!rel.empty()) return (fs::path("stdlib") / rel).generic_string();
  }
  const fs::path root = canonical_or_empty(root_file);
  if (root.empty()) return file;
  const fs::path rel = canon.lexically_relative(root.parent_path());
  return rel.empty() ? file : rel.generic_string();
}

void make_locations_portable(ir::Grammar& g, const std::string& root_file,
                             const std::vector<std::string>& stdlib_dirs) {
  std::map<std::string, std::string> renamed;  // each file resolved once
  for (std::string& loc : g.locations) {
    // "file:line:col": the file is everything before the last two colons.
    const std::size_t col = loc.rfind(':');
    if (col == std::string::npos || col == 0) continue;
    const std::size_t line = loc.rfind(':', col - 1);
    if (line == std::string::npos) continue;
    const std::string file = loc.substr(0, line);
    auto it = renamed.find(file);
    if (it == renamed.end()) {
      it = renamed.emplace(file, portable_source_name(file, root_file, stdlib_dirs)).first;
    }
    loc = it->second + loc.substr(line);
  }
}

}  // namespace ramus
