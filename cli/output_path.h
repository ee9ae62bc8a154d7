// The check every command that writes makes before it starts working: the directory of each
// output it was given must exist. A long reconstruction that fails only when it writes its
// result wastes the run, so main() checks every option registered here right after parsing.
#pragma once

#include <CLI/CLI.hpp>

namespace ramus::cli {

// Marks `option` (a file the command writes, or a folder it creates) for the check; returns it.
CLI::Option* output_path(CLI::Option* option);

// Throws UserError naming the option when a given output's directory does not exist or is not a
// directory. Options that were not given (count 0) are skipped.
void check_output_paths();

}  // namespace ramus::cli
