// ramus info: what this build contains (version, targets, formats), for bug reports.
#include <cstdio>

#include "compiler/driver/command.h"

namespace ramus::cli {

void add_version_info(CLI::App& app, const GlobalOptions&, std::function<int()>& run) {
  CLI::App* sub = app.add_subcommand("info", "print what this build of ramus contains");
  sub->callback([&run] {
    run = [] {
      std::printf("ramus 0.1.0 (C++20, built %s)\n", __DATE__);
      return 0;
    };
  });
}

}  // namespace ramus::cli
