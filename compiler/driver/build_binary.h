// `ramus build FILE --target binary -o OUT.rmb`: the grammar compiled to the binary format
// (docs/binary-format.md) instead of grown into a mesh.
#pragma once

#include <string>

#include "compiler/driver/grow_args.h"

namespace ramus::cli {

// Lowers the grammar (-D, --seed, --system apply; -n sets the stored derivation length) and
// writes its .rmb. Returns the exit code: 1 after printing the grammar's diagnostics.
int build_binary(const GrowArgs& args, const std::string& output, bool quiet);

}  // namespace ramus::cli
