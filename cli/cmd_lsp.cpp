// ramus lsp
// Runs the language server (lsp/server.h) on stdin and stdout until the client sends `exit` or
// closes the stream: diagnostics, hover, go to definition, completion, formatting and document
// symbols for .ramus files (docs/editors.md). Nothing but protocol messages goes to stdout.
#include <unistd.h>

#include "cli/command.h"
#include "lsp/server.h"

namespace ramus::cli {

void add_lsp(CLI::App& app, const GlobalOptions& global, std::function<int()>& run) {
  CLI::App* sub =
      app.add_subcommand("lsp", "run the language server (LSP 3.17 over stdin/stdout) for editors");
  sub->callback([&run] { run = [] { return lsp::run_server(STDIN_FILENO, STDOUT_FILENO); }; });
}

}  // namespace ramus::cli
