// ramus: the command-line interface. A thin layer over the libraries; see docs/cli.md.
#include <cstdint>
#include <cstdio>
#include <exception>
#include <functional>

#include "cli/command.h"
#include "cli/output_path.h"
#include "core/atomic_file.h"
#include "core/input_file.h"

int main(int argc, char** argv) {
  using namespace ramus::cli;
  CLI::App app{"ramus: a toolchain for tree grammars", "ramus"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "ramus 0.1.0");
  GlobalOptions global;
  app.add_flag("-q,--quiet", global.quiet, "no progress output");
  std::uint64_t max_file_bytes = ramus::kDefaultMaxInputFileBytes;
  app.add_option("--max-file-size", max_file_bytes,
                 "refuse any input file (scan, grammar, skeleton, .rmb, manifest) larger than "
                 "this (bytes, or with K, M, G: 2G); default 64G")
      ->transform(CLI::AsSizeValue(false));
  std::uint64_t max_points = ramus::kDefaultMaxInputPoints;
  app.add_option("--max-points", max_points,
                 "refuse a scan whose cloud would hold more points than this (after --thin); "
                 "default 1000000000")
      ->check(CLI::PositiveNumber);

  std::function<int()> run;
  for (const CommandSpec& spec : command_table()) spec.add(app, global, run);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  ramus::set_max_input_file_bytes(max_file_bytes);
  ramus::set_max_input_points(max_points);
  try {
    check_output_paths();  // before any work: a missing output directory fails at once
    return run ? run() : 2;
  } catch (const UserError& e) {
    std::fprintf(stderr, "ramus: error: %s\n", e.what());
    return 1;
  } catch (const ramus::WriteError& e) {
    std::fprintf(stderr, "ramus: error: %s\n", e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "ramus: error: out of memory\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ramus: internal error: %s\n", e.what());
    return 3;
  }
}
