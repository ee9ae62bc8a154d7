// The options every subcommand that reads a grammar shares (build, derive, preview, scan):
// FILE [-n N] [--seed S] [-D name=value]... [--system NAME] [--max-modules N] [--max-memory SIZE].

#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli/command.h"
#include "compiler/grow.h"
#include "compiler/ir.h"
#include "core/skeleton.h"
#include "grammar/loader.h"

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

// Whether `path` is a binary grammar: its first bytes are the .rmb signature, whatever its name.
bool is_binary_grammar(const std::string& path);

// Loads, checks and lowers the grammar; or, for an .rmb, decodes its lsystem (the grammar the
// runtime derives, bit for bit), with --seed applied as the runtime applies it. Options that need
// the source (-D) or another block than the one stored (--system) are UserErrors for an .rmb.
// Diagnostics are handled as by grow_for_cli.
std::optional<ir::Grammar> lower_for_cli(const GrowArgs& args);

// Grows the grammar (.ramus or .rmb, as lower_for_cli reads it). On errors in the grammar prints
// the diagnostics to stderr and returns nullopt (the caller exits with 1); warnings are printed and
// growing goes on. Derivation failures throw UserError.
std::optional<Skeleton> grow_for_cli(const GrowArgs& args);

// The `pieces` blocks an .rmb stores (section 10, formats/rmb/rmb_pieces.h) as the program that
// `--target pieces` lowers: decompiled to text (formats/rmb/rmb_decompile.h) named after the .rmb,
// so a mesh kept as a path (--mesh-paths) is found relative to the .rmb, as `ramus decompile`
// writes it beside its text. The mesh files it embeds go to `mesh_files` (name, bytes), for
// pieces::LowerPiecesOptions::mesh_files. UserError for -D (it needs the source), a damaged file
// and a file without pieces blocks; parse errors (there are none in a verified file) go to diags.
Program load_binary_pieces(const GrowArgs& args, SourceManager& sources, DiagnosticSink& diags,
                           std::vector<std::pair<std::string, std::string>>& mesh_files);

// Prints the sink's diagnostics (sorted, as text with source lines and carets) to stderr.
void print_diagnostics(const SourceManager& sources, DiagnosticSink& diags);

}  // namespace ramus::cli
