// ramus derive FILE [-n N] [--seed S] [-D name=value]... [--system NAME] [--max-modules N]
//                   [--threads T] [--print | --stats | --skeleton OUT.json]
// Derives an lsystem and prints its string (ABOP notation), its statistics, or writes the
// turtle's skeleton as JSON (formats/skeleton_json.h). The --stats lines are a contract read by
// tests:
//   length <modules> / count <symbol> <n> (by name, byte order) / sum F.<k> <value> /
//   steps <n> / time <seconds> s
#include <cstdio>
#include <map>
#include <optional>
#include <string>

#include "cli/command.h"
#include "cli/grow_args.h"
#include "cli/output_path.h"
#include "compiler/derive.h"
#include "compiler/turtle.h"
#include "core/atomic_file.h"
#include "core/number_text.h"
#include "formats/skeleton_json.h"

namespace ramus::cli {

namespace {

struct DeriveArgs {
  GrowArgs grow;
  int threads = 0;
  bool print = false, stats = false;
  std::string skeleton;
};

std::string num(double v) { return shortest_text(v); }

void print_stats(const ir::Grammar& g, const ModuleString& s, const DeriveStats& st) {
  std::vector<std::uint64_t> counts(g.symbols.size(), 0);
  // One sum per parameter F takes in the grammar, even when no F is in the string (yet).
  const int f_arity = g.symbols[ir::SymbolId(ir::TurtleOp::Forward)].arity;
  std::vector<double> f_sums(f_arity > 0 ? std::size_t(f_arity) : 0, 0.0);
  for (std::size_t i = 0; i < s.size(); ++i) {
    ++counts[s.symbol(i)];
    if (s.symbol(i) != ir::SymbolId(ir::TurtleOp::Forward)) continue;
    const std::uint32_t n = s.nparams(i);
    if (f_sums.size() < n) f_sums.resize(n, 0.0);
    for (std::uint32_t k = 0; k < n; ++k) f_sums[k] += s.param(i, k);
  }
  std::map<std::string, std::uint64_t> by_name;
  for (std::size_t k = 0; k < counts.size(); ++k) {
    if (counts[k]) by_name[g.symbols[k].name] = counts[k];
  }
  std::string out = "length " + std::to_string(s.size()) + "\n";
  for (const auto& [name, n] : by_name) out += "count " + name + " " + std::to_string(n) + "\n";
  for (std::size_t k = 0; k < f_sums.size(); ++k) {
    out += "sum F." + std::to_string(k) + " " + num(f_sums[k]) + "\n";
  }
  char t[64];
  std::snprintf(t, sizeof t, "time %.6f s\n", st.seconds);
  out += "steps " + std::to_string(st.steps) + "\n" + t;
  std::fwrite(out.data(), 1, out.size(), stdout);
}

int run_derive(const DeriveArgs& a) {
  const std::optional<ir::Grammar> lowered = lower_for_cli(a.grow);
  if (!lowered) return 1;
  const ir::Grammar& g = *lowered;
  DeriveOptions d;
  d.steps = a.grow.steps;
  d.max_modules = a.grow.max_modules;
  d.max_bytes = a.grow.max_memory;
  d.threads = a.threads;
  DeriveStats st;
  try {
    ModuleString s = derive(g, d, &st);
    if (a.stats) {
      print_stats(g, s, st);
    } else if (!a.skeleton.empty()) {
      TurtleOptions t;
      t.seed = g.settings.seed;
      t.steps = st.steps;
      t.max_modules = a.grow.max_modules;
      t.max_bytes = a.grow.max_memory;
      t.threads = a.threads;
      write_skeleton_json(a.skeleton, interpret(g, s, t));
    } else {
      std::string text = to_text(g, s);
      text += '\n';
      std::fwrite(text.data(), 1, text.size(), stdout);
    }
  } catch (const DeriveError& e) {
    throw UserError(e.what());
  }
  return 0;
}

}  // namespace

void add_derive(CLI::App& app, const GlobalOptions&, std::function<int()>& run) {
  auto args = std::make_shared<DeriveArgs>();
  CLI::App* sub = app.add_subcommand("derive", "derive an lsystem: print its string or counts");
  add_grow_options(sub, args->grow);
  sub->add_option("--threads", args->threads, "threads (default: all cores)")
      ->check(CLI::NonNegativeNumber);
  auto* p = sub->add_flag("--print", args->print, "print the string in ABOP notation (default)");
  auto* s = sub->add_flag("--stats", args->stats, "print length, symbol counts, sums, time");
  auto* k = output_path(
      sub->add_option("--skeleton", args->skeleton, "write the turtle's skeleton as JSON"));
  p->excludes(s)->excludes(k);
  s->excludes(k);
  sub->callback([args, &run] { run = [args] { return run_derive(*args); }; });
}

}  // namespace ramus::cli
