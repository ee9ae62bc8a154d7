// Folding constant expressions: `const` and `param` values, lsystem settings, probabilities,
// voxel classes. Shared by the checks (grammar/) and the lowering (compiler/), so both agree on
// the arithmetic: booleans are 1/0, trigonometry is in degrees (docs/language.md), `%` is fmod.
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "grammar/ast.h"
#include "grammar/builtins.h"

namespace ramus {

// Resolves a name to its value, or nullopt when the name is not a known constant. The named
// constants `pi` and `e` are resolved by the evaluator itself when `lookup` does not know them.
using ConstLookup = std::function<std::optional<double>(std::string_view)>;

// The value of `expr`, or nullopt when it is not constant (an unknown name, a random function,
// an unknown function) or its value is not finite (division by zero, sqrt(-1), ...).
std::optional<double> fold_constant(const ast::Expr& expr, const ConstLookup& lookup);

// Why folding failed, with the span of the sub-expression at fault.
struct FoldError {
  enum class Kind {
    UnknownName,      // a name `lookup` does not know
    UnknownFunction,  // a callee missing from grammar/builtins.h, or a wrong argument count
    Random,           // uniform/normal: not constant by definition
    NotFinite,        // the result (or a function's) is infinite or NaN
  };
  Kind kind;
  SourceSpan span;
  std::string message;  // lower case, no final period
};

struct FoldResult {
  std::optional<double> value;     // set on success
  std::optional<FoldError> error;  // set on failure
};

// Like fold_constant, but says why a value could not be computed.
FoldResult evaluate_constant(const ast::Expr& expr, const ConstLookup& lookup);

// Applies a non-random builtin to `args` (args.size() == its arity). Degrees in and out of the
// trigonometric functions. Random builtins return NaN: they need the grammar's stream.
double apply_builtin(Builtin fn, std::span<const double> args);

}  // namespace ramus
