// The options every subcommand that reads a grammar shares (build, derive, preview, scan):
// FILE [-n N] [--seed S] [-D name=value]... [--system NAME] [--max-modules N] [--max-memory SIZE].

#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cli/command.h"
#include "compiler/grow.h"
#include "compiler/ir.h"
#include "core/skeleton.h"

namespace ramus::cli {

struct GrowArgs {
  std::string file;
  std::optional<int> steps;
  std::optional<std::uint64_t> seed;
  std::vector<std::string> defines;
  std::string system;
  std::uint64_t max_modules = 100'000'000;
  std::uint64_t max_memory = 0;  // bytes; 0: 80% of physical memory
};

void add_grow_options(CLI::App* sub, GrowArgs& args);
// --max-memory SIZE, for the subcommands that declare their own grow options.
void add_max_memory_option(CLI::App* sub, std::uint64_t& bytes);

// The options as the pipeline takes them (-D parsed; throws UserError on a malformed one).
GrowOptions to_grow_options(const GrowArgs& args);

// Loads, checks and lowers the grammar. Diagnostics are handled as by grow_for_cli.
std::optional<ir::Grammar> lower_for_cli(const GrowArgs& args);

// Grows the grammar. On errors in the grammar prints the diagnostics to stderr and returns
// nullopt (the caller exits with 1); warnings are printed and growing goes on. Derivation
// failures throw UserError.
std::optional<Skeleton> grow_for_cli(const GrowArgs& args);
// The same for grammar text already in memory (a decompiled .rmb), named args.file.
std::optional<Skeleton> grow_text_for_cli(const GrowArgs& args, const std::string& text);

// Prints the sink's diagnostics (sorted, as text with source lines and carets) to stderr.
void print_diagnostics(const SourceManager& sources, DiagnosticSink& diags);

}  // namespace ramus::cli
