// ramus fmt FILE... [--check]
// Rewrites each file in the canonical layout (docs/formatting.md), atomically. With --check
// nothing is written: the files that would change are named on stdout and the exit code is 1.
// A file with syntax errors is reported and left untouched (exit 1).
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/command.h"
#include "core/atomic_file.h"
#include "core/input_file.h"
#include "grammar/format.h"
#include "grammar/parser.h"

namespace ramus::cli {

namespace {

struct FmtArgs {
  std::vector<std::string> files;
  bool check = false;
};

enum class Outcome { Unchanged, Changed, Failed };

// The formatted text of `path`, or nullopt (after reporting why) when it cannot be formatted.
std::optional<std::string> formatted(const std::string& path, const std::string& text) {
  SourceManager sources;
  DiagnosticSink sink;
  ast::File file = parse(sources, sources.add(path, text), sink);
  if (sink.has_errors()) {
    sink.sort();
    std::string out = render_text(sources, sink.all());
    std::fwrite(out.data(), 1, out.size(), stderr);
    std::fprintf(stderr, "ramus fmt: %s has errors; left unchanged\n", path.c_str());
    return std::nullopt;
  }
  std::string result = format_file(file, sources);
  // The formatter must never change what a file means: parse the result and compare.
  DiagnosticSink again_sink;
  ast::File again = parse(sources, sources.add(path, result), again_sink);
  if (again_sink.has_errors() || !(again == file)) {
    std::fprintf(stderr,
                 "ramus fmt: internal error: formatting %s would change its meaning; "
                 "left unchanged\n",
                 path.c_str());
    return std::nullopt;
  }
  return result;
}

Outcome format_one(const std::string& path, const FmtArgs& args, const GlobalOptions& global) {
  std::string text, error;
  if (!read_input_file(path, text, error)) {
    std::fprintf(stderr, "ramus fmt: error: cannot read %s: %s\n", path.c_str(), error.c_str());
    return Outcome::Failed;
  }
  std::optional<std::string> result = formatted(path, text);
  if (!result) return Outcome::Failed;
  if (*result == text) return Outcome::Unchanged;
  if (args.check) {
    std::printf("%s\n", path.c_str());
  } else {
    write_file_atomically(path, *result);
    if (!global.quiet) std::fprintf(stderr, "formatted %s\n", path.c_str());
  }
  return Outcome::Changed;
}

int run_fmt(const FmtArgs& args, const GlobalOptions& global) {
  bool failed = false, changed = false;
  for (const std::string& path : args.files) {
    Outcome o = format_one(path, args, global);
    failed = failed || o == Outcome::Failed;
    changed = changed || o == Outcome::Changed;
  }
  if (args.check && changed && !global.quiet) {
    std::fprintf(stderr, "ramus fmt --check: the files above are not formatted\n");
  }
  return failed || (args.check && changed) ? 1 : 0;
}

}  // namespace

void add_fmt(CLI::App& app, const GlobalOptions& global, std::function<int()>& run) {
  auto args = std::make_shared<FmtArgs>();
  CLI::App* sub = app.add_subcommand("fmt", "rewrite grammar files in the canonical layout");
  sub->add_option("files", args->files, "the .ramus files to format")->required();
  sub->add_flag("--check", args->check,
                "write nothing; name the files that would change and exit 1 if any");
  sub->callback(
      [args, &global, &run] { run = [args, &global] { return run_fmt(*args, global); }; });
}

}  // namespace ramus::cli
