#include "compiler/driver/grow_args.h"

#include <cstdio>

#include "compiler/driver/defines.h"
#include "compiler/grow.h"

namespace ramus::cli {

void add_grow_options(CLI::App* sub, GrowArgs& a) {
  sub->add_option("file", a.file, "grammar file (.ramus)")->required();
  sub->add_option("-n,--steps", a.steps, "derivation steps (default: the grammar's derive)")
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--seed", a.seed, "random seed (default: the grammar's seed)");
  sub->add_option("-D,--define", a.defines, "override a param: name=value");
  sub->add_option("--system", a.system, "lsystem block (default: the first)");
  sub->add_option("--max-modules", a.max_modules, "stop with an error above this length");
}

std::optional<Skeleton> grow_for_cli(const GrowArgs& a) {
  GrowOptions opt;
  opt.system = a.system;
  opt.steps = a.steps;
  opt.seed = a.seed;
  opt.defines = parse_defines(a.defines);
  opt.max_modules = a.max_modules;
  SourceManager sources;
  DiagnosticSink diags;
  try {
    Skeleton s = grow_file(a.file, opt, sources, diags);
    if (!diags.all().empty()) {
      diags.sort();
      std::fputs(render_text(sources, diags.all()).c_str(), stderr);
    }
    return s;
  } catch (const GrowError& e) {
    diags.sort();
    std::fputs(render_text(sources, diags.all()).c_str(), stderr);
    if (!diags.has_errors()) throw UserError(e.what());
    return std::nullopt;
  }
}

}  // namespace ramus::cli
