#include "lsp/import_path.h"

#include <algorithm>
#include <filesystem>

#include "grammar/loader.h"

namespace ramus::lsp {

namespace fs = std::filesystem;

std::optional<std::string> resolve_import(const ast::Import& import, const std::string& importer) {
  std::error_code ec;
  if (import.is_file) {
    fs::path p = fs::path(importer).parent_path() / import.path;
    if (fs::exists(p, ec)) return fs::absolute(p, ec).lexically_normal().string();
    return std::nullopt;
  }
  std::string rel = import.path;
  std::replace(rel.begin(), rel.end(), '.', '/');
  rel += ".ramus";
  for (const std::string& dir : default_stdlib_dirs()) {
    fs::path p = fs::path(dir) / rel;
    if (fs::exists(p, ec)) return fs::absolute(p, ec).lexically_normal().string();
  }
  return std::nullopt;
}

}  // namespace ramus::lsp
