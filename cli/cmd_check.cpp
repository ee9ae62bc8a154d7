// ramus check FILE... [--diagnostics=text|json] [-D name=value]...
// Loads each file with its imports, runs the semantic checks and prints every diagnostic: as
// text on stderr (file:line:col, source line, caret, notes), or as one JSON document on stdout.
// Exit 0 when there is no error (warnings allowed), 1 with errors, 2 on a usage error.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "cli/command.h"
#include "cli/defines.h"
#include "grammar/check.h"
#include "grammar/loader.h"

namespace ramus::cli {

namespace {

struct CheckArgs {
  std::vector<std::string> files;
  std::string format = "text";
  std::vector<std::string> defines;
};

// Every -D must name a `param` of the file (or its imports); a `const` cannot be overridden.
bool defines_name_params(const Program& program, const std::string& file,
                         const std::vector<std::pair<std::string, double>>& defines) {
  bool ok = true;
  for (const auto& [name, value] : defines) {
    DefineTarget t = find_define_target(program, name);
    if (t == DefineTarget::Param) continue;
    ok = false;
    if (t == DefineTarget::Const) {
      std::fprintf(stderr, "ramus: error: -D %s: '%s' is a const in %s, not a param\n",
                   name.c_str(), name.c_str(), file.c_str());
    } else {
      std::fprintf(stderr, "ramus: error: -D %s: %s has no param named '%s'\n", name.c_str(),
                   file.c_str(), name.c_str());
    }
  }
  return ok;
}

std::string summary(const DiagnosticSink& sink) {
  auto count = [](std::size_t n, const char* what) {
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
  };
  return count(sink.error_count(), "error") + ", " + count(sink.warning_count(), "warning");
}

int run_check(const CheckArgs& args, const GlobalOptions& global) {
  CheckOptions options;
  try {
    options.defines = parse_defines(args.defines);
  } catch (const UserError& e) {
    std::fprintf(stderr, "ramus check: %s\n", e.what());
    return 2;
  }
  SourceManager sources;
  DiagnosticSink sink;
  bool defines_ok = true;
  for (const std::string& file : args.files) {
    Program program = load_program(file, sources, sink);
    if (program.files.empty()) continue;  // unreadable: E0001 is in the sink
    defines_ok = defines_name_params(program, file, options.defines) && defines_ok;
    check_program(program, sources, sink, options);
  }
  sink.sort();
  if (args.format == "json") {
    std::string out = render_json(sources, sink.all());
    std::fwrite(out.data(), 1, out.size(), stdout);
  } else {
    bool color = isatty(fileno(stderr)) && !std::getenv("NO_COLOR");
    std::string out = render_text(sources, sink.all(), color);
    std::fwrite(out.data(), 1, out.size(), stderr);
    if (!sink.all().empty() && !global.quiet) {
      std::fprintf(stderr, "%s\n", summary(sink).c_str());
    }
  }
  return sink.has_errors() || !defines_ok ? 1 : 0;
}

}  // namespace

void add_check(CLI::App& app, const GlobalOptions& global, std::function<int()>& run) {
  auto args = std::make_shared<CheckArgs>();
  CLI::App* sub = app.add_subcommand("check", "check grammar files and print their diagnostics");
  sub->add_option("files", args->files, "the .ramus files to check")->required();
  sub->add_option("--diagnostics", args->format, "text (on stderr) or json (on stdout)")
      ->check(CLI::IsMember({"text", "json"}));
  sub->add_option("-D", args->defines, "override a param: -D name=value")->type_name("NAME=VALUE");
  sub->callback(
      [args, &global, &run] { run = [args, &global] { return run_check(*args, global); }; });
}

}  // namespace ramus::cli
