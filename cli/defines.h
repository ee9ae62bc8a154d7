// `-D name=value` on the command line: overrides of a grammar's `param`s. Shared by every
// subcommand that grows a grammar (derive, build, preview, scan, ...).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace ramus::cli {

// Parses "name=value" (value a finite number, e.g. 0.5, -2, 1e-3). Throws UserError
// (cli/command.h) naming the bad text.
std::pair<std::string, double> parse_define(const std::string& text);

// Parses every entry; a name given twice keeps the last value.
std::vector<std::pair<std::string, double>> parse_defines(const std::vector<std::string>& texts);

}  // namespace ramus::cli
