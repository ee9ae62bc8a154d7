// Loading a program: the root file, parsed, and every file it imports (transitively), each
// parsed once. `import "rel/path.ramus";` is resolved relative to the importing file;
// `import a.b;` names <stdlib>/a/b.ramus in the first stdlib directory that has it.
// Errors: E0001 (file unreadable), E0601 (import not found), E0602 (import cycle), plus what
// the parser reports; the program holds every file that could be read.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "grammar/ast.h"
#include "grammar/diagnostic.h"
#include "grammar/source.h"

namespace ramus {

struct Program {
  std::vector<ast::File> files;                     // files[0] is the root; each import once
  std::vector<std::vector<std::uint32_t>> imports;  // per file: indices into files it imports
};

struct LoadOptions {
  // Where `import a.b;` looks. Empty: default_stdlib_dirs().
  std::vector<std::string> stdlib_dirs;
};

// The environment variable RAMUS_STDLIB if set (a ':'-separated list), else the stdlib/ folder
// of the source tree this library was built from.
std::vector<std::string> default_stdlib_dirs();

// Reads and parses `path` and its imports. When the root cannot be read, E0001 is reported and
// the program is empty (no files).
Program load_program(const std::string& path, SourceManager& sm, DiagnosticSink& diags,
                     const LoadOptions& options = {});
// The same for text already in memory (tests, fuzzing, stdin); `name` is what diagnostics print
// and the base for relative imports.
Program load_program_text(std::string name, std::string text, SourceManager& sm,
                          DiagnosticSink& diags, const LoadOptions& options = {});

}  // namespace ramus
