// Portable source locations for .rmb files (docs/binary-format.md, section 4 locations).
//
// Lowering records each location as "file:line:col" with the file name as the loader saw it:
// the path as typed on the command line for the root, joined paths for imports and absolute
// paths into the stdlib directory. Stored like that, the bytes of an .rmb would depend on the
// working directory and on where the checkout lives. Before encoding, `ramus build` rewrites
// each file name to a form that depends on the grammar alone:
//   - a file under a stdlib directory -> "stdlib/<path inside that directory>"
//   - any other file                  -> its path relative to the root grammar's directory
// Names that are not files on disk ("<stdin>", "<unknown>") are kept as they are.
#pragma once

#include <string>
#include <vector>

#include "compiler/ir.h"

namespace ramus {

// The portable name of `file` (a path as the loader recorded it).
std::string portable_source_name(const std::string& file, const std::string& root_file,
                                 const std::vector<std::string>& stdlib_dirs);

// Rewrites the file part of every entry of g.locations with portable_source_name.
void make_locations_portable(ir::Grammar& g, const std::string& root_file,
                             const std::vector<std::string>& stdlib_dirs);

}  // namespace ramus
