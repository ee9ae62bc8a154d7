// The expression compiler: ast::Expr -> flat bytecode in an ir::Grammar (compiler/expr_vm.h runs
// it). Names resolve to formal parameters (slots) first, then to constants and params, then to
// `pi` and `e`. An expression that reads no parameter and draws nothing is folded to a constant
// here, so a bad constant (1/0) is reported at its source position before derivation starts.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "compiler/ir.h"
#include "grammar/ast.h"
#include "grammar/source.h"

namespace ramus {

struct CompileError : std::runtime_error {
  CompileError(std::string msg, SourceSpan s) : std::runtime_error(std::move(msg)), span(s) {}
  SourceSpan span;
};

struct ExprScope {
  std::vector<std::pair<std::string, std::uint16_t>> params;  // formal name -> slot
  const std::vector<ir::Constant>* constants = nullptr;
  bool allow_random = true;
};

// Compiles `e`; `where` is the "file:line:col" recorded for error messages.
ir::CodeId compile_expr(ir::Grammar& g, const ast::Expr& e, const ExprScope& scope,
                        const std::string& where);

// Adds a constant expression (for built-in defaults and tests).
ir::CodeId constant_code(ir::Grammar& g, double value, const std::string& where);

// Evaluates a code that reads no parameters (constants, settings, axiom arguments).
double eval_constant(const ir::Grammar& g, ir::CodeId c);

}  // namespace ramus
