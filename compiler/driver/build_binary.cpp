#include "compiler/driver/build_binary.h"

#include <cstdio>
#include <filesystem>

#include "compiler/rmb_codec.h"
#include "core/atomic_file.h"

namespace ramus::cli {

int build_binary(const GrowArgs& a, const std::string& output, bool quiet) {
  if (std::filesystem::path(output).extension() != ".rmb") {
    throw UserError("--target binary writes an .rmb file, not " + output);
  }
  std::optional<ir::Grammar> lowered = lower_for_cli(a);
  if (!lowered) return 1;
  ir::Grammar& g = *lowered;
  if (a.steps) g.settings.derive = *a.steps;
  const std::string bytes = encode_rmb(g);
  write_file_atomically(output, bytes);
  if (!quiet) {
    std::fprintf(stderr, "ramus: wrote %s (%zu bytes: %zu symbols, %zu productions)\n",
                 output.c_str(), bytes.size(), g.symbols.size(), g.productions.size());
  }
  return 0;
}

}  // namespace ramus::cli
