#include "cli/output_path.h"

#include <filesystem>
#include <vector>

#include "cli/command.h"

namespace ramus::cli {
namespace {

// The registered options. The CLI builds its one App once per process, so the list lives as
// long as the options it points at.
std::vector<const CLI::Option*>& registered() {
  static std::vector<const CLI::Option*> options;
  return options;
}

void check_one(const CLI::Option& option, const std::string& path) {
  if (path.empty() || path == "-") return;
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  if (dir.empty()) return;  // the current directory
  std::error_code ec;
  if (std::filesystem::is_directory(dir, ec)) return;
  throw UserError(option.get_name() + ": cannot write " + path + ": the directory " + dir.string() +
                  (std::filesystem::exists(dir, ec) ? " is not a directory" : " does not exist"));
}

}  // namespace

CLI::Option* output_path(CLI::Option* option) {
  registered().push_back(option);
  return option;
}

void check_output_paths() {
  for (const CLI::Option* option : registered()) {
    if (option->count() == 0) continue;
    for (const std::string& path : option->results()) check_one(*option, path);
  }
}

}  // namespace ramus::cli
