#include "cli/grow_args.h"

#include <cstdio>

#include "cli/defines.h"
#include "compiler/pipeline.h"

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

}  // namespace

void add_grow_options(CLI::App* sub, GrowArgs& a) {
  sub->add_option("file", a.file, "grammar file (.ramus)")->required();
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
  return run_reporting<ir::Grammar>(a, &lower_file);
}

std::optional<Skeleton> grow_for_cli(const GrowArgs& a) {
  return run_reporting<Skeleton>(a, &grow_file);
}

std::optional<Skeleton> grow_text_for_cli(const GrowArgs& a, const std::string& text) {
  return run_reporting<Skeleton>(
      a, [&](const std::string& name, const GrowOptions& o, SourceManager& s, DiagnosticSink& d) {
        return grow_text(name, text, o, s, d);
      });
}

void print_diagnostics(const SourceManager& sources, DiagnosticSink& diags) {
  if (diags.all().empty()) return;
  diags.sort();
  std::fputs(render_text(sources, diags.all()).c_str(), stderr);
}

}  // namespace ramus::cli
