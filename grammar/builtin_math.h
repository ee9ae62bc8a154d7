// The arithmetic of the non-random builtins (grammar/builtins.h), in one place for the constant
// folder (grammar/const_eval.cpp) and the expression VM (compiler/expr_vm.cpp), so a value folded
// at compile time is the value the VM computes. Inline: the VM calls it in its inner loop.
// Trigonometry is in degrees in and out (docs/language.md). No domain checks here: a bad argument
// gives NaN or an infinity, which each caller reports in its own way.
#pragma once

#include <cmath>

#include "grammar/builtins.h"

namespace ramus {

inline constexpr double kDegree = kPi / 180.0;

// `a` holds the builtin's arity of arguments. Random builtins return NaN: they need the
// grammar's stream, which only the VM has.
inline double builtin_math(Builtin fn, const double* a) {
  switch (fn) {
    case Builtin::Sin:
      return std::sin(a[0] * kDegree);
    case Builtin::Cos:
      return std::cos(a[0] * kDegree);
    case Builtin::Tan:
      return std::tan(a[0] * kDegree);
    case Builtin::Asin:
      return std::asin(a[0]) / kDegree;
    case Builtin::Acos:
      return std::acos(a[0]) / kDegree;
    case Builtin::Atan:
      return std::atan(a[0]) / kDegree;
    case Builtin::Atan2:
      return std::atan2(a[0], a[1]) / kDegree;
    case Builtin::Sqrt:
      return std::sqrt(a[0]);
    case Builtin::Exp:
      return std::exp(a[0]);
    case Builtin::Log:
      return std::log(a[0]);
    case Builtin::Log10:
      return std::log10(a[0]);
    case Builtin::Pow:
      return std::pow(a[0], a[1]);
    case Builtin::Abs:
      return std::fabs(a[0]);
    case Builtin::Floor:
      return std::floor(a[0]);
    case Builtin::Ceil:
      return std::ceil(a[0]);
    case Builtin::Round:
      return std::round(a[0]);
    case Builtin::Min:
      return std::fmin(a[0], a[1]);
    case Builtin::Max:
      return std::fmax(a[0], a[1]);
    case Builtin::Clamp:
      return std::fmin(std::fmax(a[0], a[1]), a[2]);
    case Builtin::Sign:
      return a[0] > 0 ? 1.0 : (a[0] < 0 ? -1.0 : 0.0);
    case Builtin::Uniform:
    case Builtin::Normal:
      return std::nan("");
  }
  return std::nan("");
}

}  // namespace ramus
