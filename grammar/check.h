// Semantic checks over a loaded program (the root file and its imports): names, arities, types,
// values, and the warnings (unused constants and productions, shadowed productions). Every
// diagnostic points at the node at fault, with notes at related places. The passes run in the
// order listed in check.cpp; each concern lives in its own check_<concern>.cpp.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "grammar/diagnostic.h"
#include "grammar/loader.h"
#include "grammar/source.h"

namespace ramus {

struct CheckOptions {
  // -D name=value: overrides a `param` of the program (the caller checks that it names one,
  // see find_define_target). Checks fold settings such as `derive` with these values.
  std::vector<std::pair<std::string, double>> defines;
};

void check_program(const Program& program, const SourceManager& sources, DiagnosticSink& sink);
void check_program(const Program& program, const SourceManager& sources, DiagnosticSink& sink,
                   const CheckOptions& options);

// What a -D name refers to: a `param` (overridable), a `const` (not overridable) or nothing.
enum class DefineTarget { Param, Const, Unknown };
DefineTarget find_define_target(const Program& program, std::string_view name);

}  // namespace ramus
