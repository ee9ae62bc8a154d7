// The table of subcommands, in the order `ramus --help` lists them.
#include "cli/command.h"

namespace ramus::cli {

// Each is defined in cmd_<name>.cpp.
void add_version_info(CLI::App&, const GlobalOptions&, std::function<int()>&);
void add_check(CLI::App&, const GlobalOptions&, std::function<int()>&);
void add_fmt(CLI::App&, const GlobalOptions&, std::function<int()>&);
void add_derive(CLI::App&, const GlobalOptions&, std::function<int()>&);
void add_compress(CLI::App&, const GlobalOptions&, std::function<int()>&);
void add_enhance(CLI::App&, const GlobalOptions&, std::function<int()>&);
void add_symmetrize(CLI::App&, const GlobalOptions&, std::function<int()>&);
void add_propagate(CLI::App&, const GlobalOptions&, std::function<int()>&);
void add_inspect(CLI::App&, const GlobalOptions&, std::function<int()>&);
void add_build(CLI::App&, const GlobalOptions&, std::function<int()>&);
void add_preview(CLI::App&, const GlobalOptions&, std::function<int()>&);
void add_view(CLI::App&, const GlobalOptions&, std::function<int()>&);
void add_reconstruct(CLI::App&, const GlobalOptions&, std::function<int()>&);
void add_classify(CLI::App&, const GlobalOptions&, std::function<int()>&);
void add_scan(CLI::App&, const GlobalOptions&, std::function<int()>&);
void add_dump(CLI::App&, const GlobalOptions&, std::function<int()>&);
void add_decompile(CLI::App&, const GlobalOptions&, std::function<int()>&);
void add_infer(CLI::App&, const GlobalOptions&, std::function<int()>&);
void add_compare(CLI::App&, const GlobalOptions&, std::function<int()>&);
void add_lsp(CLI::App&, const GlobalOptions&, std::function<int()>&);
void add_tiles(CLI::App&, const GlobalOptions&, std::function<int()>&);

const std::vector<CommandSpec>& command_table() {
  static const std::vector<CommandSpec> table = {
      {"info", add_version_info},
      {"check", add_check},
      {"fmt", add_fmt},
      {"derive", add_derive},
      {"compress", add_compress},
      {"enhance", add_enhance},
      {"symmetrize", add_symmetrize},
      {"propagate", add_propagate},
      {"infer", add_infer},
      {"compare", add_compare},
      {"inspect", add_inspect},
      {"build", add_build},
      {"preview", add_preview},
      {"view", add_view},
      {"tiles", add_tiles},
      {"reconstruct", add_reconstruct},
      {"classify", add_classify},
      {"scan", add_scan},
      {"dump", add_dump},
      {"decompile", add_decompile},
      {"lsp", add_lsp},
  };
  return table;
}

}  // namespace ramus::cli
