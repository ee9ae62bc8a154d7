// The functions and named constants expressions may use: one table read by the checks (names,
// arity), the formatter, lowering (opcodes) and the decompiler. Trigonometry is in degrees,
// like every angle in ramus (docs/language.md).
#pragma once

#include <cstdint>
#include <string_view>

namespace ramus {

enum class Builtin : std::uint8_t {
  Sin, Cos, Tan, Asin, Acos, Atan, Atan2, Sqrt, Exp, Log, Log10, Pow, Abs, Floor, Ceil, Round,
  Min, Max, Clamp, Sign, Uniform, Normal,
};

struct BuiltinInfo {
  Builtin id;
  std::string_view name;
  std::uint8_t arity;
  bool random;  // draws from the grammar's seeded stream (not allowed in `const`)
};

inline constexpr BuiltinInfo kBuiltins[] = {
    {Builtin::Sin, "sin", 1, false},     {Builtin::Cos, "cos", 1, false},
    {Builtin::Tan, "tan", 1, false},     {Builtin::Asin, "asin", 1, false},
    {Builtin::Acos, "acos", 1, false},   {Builtin::Atan, "atan", 1, false},
    {Builtin::Atan2, "atan2", 2, false}, {Builtin::Sqrt, "sqrt", 1, false},
    {Builtin::Exp, "exp", 1, false},     {Builtin::Log, "log", 1, false},
    {Builtin::Log10, "log10", 1, false}, {Builtin::Pow, "pow", 2, false},
    {Builtin::Abs, "abs", 1, false},     {Builtin::Floor, "floor", 1, false},
    {Builtin::Ceil, "ceil", 1, false},   {Builtin::Round, "round", 1, false},
    {Builtin::Min, "min", 2, false},     {Builtin::Max, "max", 2, false},
    {Builtin::Clamp, "clamp", 3, false}, {Builtin::Sign, "sign", 1, false},
    {Builtin::Uniform, "uniform", 2, true}, {Builtin::Normal, "normal", 2, true},
};

inline const BuiltinInfo* find_builtin(std::string_view name) {
  for (const auto& b : kBuiltins) {
    if (b.name == name) return &b;
  }
  return nullptr;
}

// Named constants usable in any expression.
inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kE = 2.71828182845904523536;
inline bool find_named_constant(std::string_view name, double& value) {
  if (name == "pi") { value = kPi; return true; }
  if (name == "e") { value = kE; return true; }
  return false;
}

}  // namespace ramus
