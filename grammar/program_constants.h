// The values of a program's `const` and `param` bindings, for the lowerings that need numbers
// outside an lsystem block (pieces blocks, their binary encoding). Files are visited imports
// first, so a file sees the names it imports; `-D name=value` replaces a param.
#pragma once

#include <functional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "grammar/const_eval.h"
#include "grammar/loader.h"

namespace ramus {

using ConstantDefines = std::vector<std::pair<std::string, double>>;

// Told about each binding whose value cannot be computed (the binding is then left out).
using ConstantFailure = std::function<void(const ast::Expr& value, const FoldResult& why)>;

std::unordered_map<std::string, double> program_constants(const Program& program,
                                                          const ConstantDefines& defines,
                                                          const ConstantFailure& on_failure = {});

// Looks names up in `values` (for fold_constant / evaluate_constant).
ConstLookup lookup_in(const std::unordered_map<std::string, double>& values);

}  // namespace ramus
