#include "cli/grow_args.h"

#include <cstdio>
#include <fstream>

#include "cli/defines.h"
#include "cli/read_file.h"
#include "compiler/pipeline.h"
#include "formats/rmb/rmb_codec.h"
#include "formats/rmb/rmb_decompile.h"

namespace ramus::cli {

namespace {

// Runs one front-end step (lower_file, grow_file or grow_text) with the CLI's handling of
// diagnostics: warnings are printed and the result returned; errors in the grammar are printed and
// give nullopt; a GrowError without a diagnostic (no such lsystem, ...) becomes a UserError.
template <class Result, class Step>
std::optional<Result> run_reporting(const GrowArgs& a, const Step& step) {
  const GrowOptions opt = to_grow_options(a);
  SourceManager sources;
  DiagnosticSink diags;
  try {
    Result r = step(a.file, opt, sources, diags);
    print_diagnostics(sources, diags);
    return r;
  } catch (const GrowError& e) {
    print_diagnostics(sources, diags);
    if (!diags.has_errors()) throw UserError(e.what());
    return std::nullopt;
  }
}

void refuse_defines(const GrowArgs& a) {
  if (!a.defines.empty()) {
    throw UserError("-D/--define needs the grammar's source; " + a.file +
                    " is a compiled binary grammar (define the param when building it)");
  }
}

// The lsystem of an .rmb as the runtime loads it (runtime/ramus_runtime.cpp): decoded, with the
// seed override in its settings, so the axiom's arguments and every pass draw from that seed.
ir::Grammar load_binary_grammar(const GrowArgs& a) {
  refuse_defines(a);
  ir::Grammar g;
  try {
    g = decode_rmb(read_file_bytes(a.file));
  } catch (const RmbError& e) {
    throw UserError(a.file + ": " + e.what());
  }
  if (!rmb_has_lsystem(g)) throw UserError(a.file + " holds no lsystem block (only pieces)");
  if (!a.system.empty() && a.system != g.name) {
    throw UserError("--system " + a.system + ": " + a.file + " holds the lsystem '" + g.name +
                    "' only");
  }
  if (a.seed) g.settings.seed = *a.seed;
  return g;
}

}  // namespace

bool is_binary_grammar(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char head[4] = {};
  return in.read(head, 4) && std::string_view(head, 4) == std::string_view("RMB\x1a", 4);
}

void add_grow_options(CLI::App* sub, GrowArgs& a) {
  sub->add_option("file", a.file, "grammar file (.ramus, or a binary grammar .rmb)")->required();
  sub->add_option("-n,--steps", a.steps, "derivation steps (default: the grammar's derive)")
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--seed", a.seed, "random seed (default: the grammar's seed)");
  sub->add_option("-D,--define", a.defines, "override a param: name=value");
  sub->add_option("--system", a.system, "lsystem block (default: the first)");
  sub->add_option("--max-modules", a.max_modules, "stop with an error above this length");
  add_max_memory_option(sub, a.max_memory);
}

void add_max_memory_option(CLI::App* sub, std::uint64_t& bytes) {
  sub->add_option("--max-memory", bytes,
                  "stop with an error when the derivation would need more memory (bytes, or with "
                  "K, M, G: 512M); default: 80% of physical memory")
      ->transform(CLI::AsSizeValue(false));
}

GrowOptions to_grow_options(const GrowArgs& a) {
  GrowOptions opt;
  opt.system = a.system;
  opt.steps = a.steps;
  opt.seed = a.seed;
  opt.defines = parse_defines(a.defines);
  opt.max_modules = a.max_modules;
  opt.max_bytes = a.max_memory;
  return opt;
}

std::optional<ir::Grammar> lower_for_cli(const GrowArgs& a) {
  if (is_binary_grammar(a.file)) return load_binary_grammar(a);
  return run_reporting<ir::Grammar>(a, &lower_file);
}

std::optional<Skeleton> grow_for_cli(const GrowArgs& a) {
  if (is_binary_grammar(a.file)) {
    try {
      return grow_grammar(load_binary_grammar(a), to_grow_options(a));
    } catch (const GrowError& e) {
      throw UserError(e.what());
    }
  }
  return run_reporting<Skeleton>(a, &grow_file);
}

Program load_binary_pieces(const GrowArgs& a, SourceManager& sources, DiagnosticSink& diags,
                           std::vector<std::pair<std::string, std::string>>& mesh_files) {
  refuse_defines(a);
  RmbContents pieces_only;  // no lsystem and no voxels: the text holds the pieces blocks alone
  try {
    pieces_only.pieces = decode_rmb_contents(read_file_bytes(a.file)).pieces;
  } catch (const RmbError& e) {
    throw UserError(a.file + ": " + e.what());
  }
  if (pieces_only.pieces.empty()) throw UserError(a.file + " holds no pieces block");
  std::string text;
  try {
    text = decompile(pieces_only);
  } catch (const DecompileError& e) {
    throw UserError(a.file + ": " + e.what());
  }
  mesh_files.clear();
  for (RmbMeshFile& m : pieces_only.pieces.meshes) {
    mesh_files.emplace_back(std::move(m.name), std::move(m.bytes));
  }
  return load_program_text(a.file, std::move(text), sources, diags);
}

void print_diagnostics(const SourceManager& sources, DiagnosticSink& diags) {
  if (diags.all().empty()) return;
  diags.sort();
  std::fputs(render_text(sources, diags.all()).c_str(), stderr);
}

}  // namespace ramus::cli
