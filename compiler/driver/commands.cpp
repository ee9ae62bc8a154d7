// The table of subcommands, in the order `ramus --help` lists them.
#include "compiler/driver/command.h"

namespace ramus::cli {

// Each is defined in cmd_<name>.cpp.
void add_version_info(CLI::App&, const GlobalOptions&, std::function<int()>&);

const std::vector<CommandSpec>& command_table() {
  static const std::vector<CommandSpec> table = {
      {"info", add_version_info},
  };
  return table;
}

}  // namespace ramus::cli
