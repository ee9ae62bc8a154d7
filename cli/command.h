// The CLI's subcommands. Each lives in its own cmd_<name>.cpp and is listed once in
// commands.cpp's table (explicit registration: nothing registers itself statically).
//
// Exit codes: 0 success, 1 errors in the input (diagnostics, bad scan, ...), 2 usage.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

namespace ramus::cli {

// Options every subcommand may read.
struct GlobalOptions {
  bool quiet = false;
};

// A subcommand adds itself to `app` and stores in `run` what to do when it is chosen.
struct CommandSpec {
  const char* name;
  void (*add)(CLI::App& app, const GlobalOptions& global, std::function<int()>& run);
};

const std::vector<CommandSpec>& command_table();

// Thrown by commands for errors that are the user's input, not a bug: printed as
// "ramus: error: <message>" with exit code 1.
struct UserError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace ramus::cli
