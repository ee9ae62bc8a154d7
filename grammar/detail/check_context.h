// Shared state of the semantic checks (grammar/check*.cpp): the symbol tables of every file of
// the program, what each file can see (itself and, transitively, its imports), and the expression
// checker every pass uses. Internal to grammar/.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "grammar/ast.h"
#include "grammar/check.h"
#include "grammar/diagnostic.h"

namespace ramus::detail {

enum class Type { Number, Boolean, Error };  // Error: already reported, stay silent

struct ConstInfo {
  const ast::Binding* binding = nullptr;
  bool is_param = false;
  std::uint32_t file = 0;
  std::uint32_t order = 0;  // position among the file's bindings (constants use earlier ones)
  Type type = Type::Number;
  std::optional<double> value;  // folded value (a -D value for an overridden param)
  bool used = false;
};

struct ModuleInfo {
  const ast::ModulePattern* pattern = nullptr;  // from a `module` declaration
  std::uint32_t file = 0;
};

// Formal parameters of a production: name -> where it is bound.
using Formals = std::unordered_map<std::string, SourceSpan>;

// Where an expression sits, which decides what it may refer to.
struct ExprEnv {
  std::uint32_t file = 0;
  const Formals* formals = nullptr;
  // When set, the expression must be constant: random functions are errors (E0208), and the
  // text says where, e.g. "a constant" or "the setting 'derive'".
  const char* constant_context = nullptr;
  // For a constant's own value: bindings of the same file at or after this order are not yet
  // defined (E0110).
  std::uint32_t defined_before = UINT32_MAX;
  bool unknown_names_ok = false;  // `select` keys name the predecessor's parameters of any rule
};

class CheckContext {
 public:
  CheckContext(const Program& program, const SourceManager& sources, DiagnosticSink& sink,
               const CheckOptions& options);

  const Program& program;
  const SourceManager& sources;
  DiagnosticSink& sink;
  const CheckOptions& options;

  // Per file: the files whose declarations it sees, itself first.
  std::vector<std::vector<std::uint32_t>> visible;
  // Per file: its own constants/params and module declarations.
  std::vector<std::unordered_map<std::string, ConstInfo>> consts;
  std::vector<std::unordered_map<std::string, ModuleInfo>> modules;

  // Warnings are given for the root file only: imported files are libraries whose constants
  // and productions exist for their importers.
  bool warn_in(std::uint32_t file) const { return file == 0; }

  ConstInfo* find_const(std::uint32_t file, const std::string& name);
  const ModuleInfo* find_module(std::uint32_t file, const std::string& name) const;

  // Checks names, calls and types; returns the type (Error when something was reported).
  Type check_expr(const ast::Expr& e, const ExprEnv& env);
  // check_expr, then E0204 when the expression is boolean.
  void check_number(const ast::Expr& e, const ExprEnv& env, std::string_view what);
  // Folds with the constants' values (no diagnostics; nullopt when not constant, e.g. when it
  // names one of `formals`).
  std::optional<double> fold(const ast::Expr& e, std::uint32_t file,
                             const Formals* formals = nullptr);

  // Reports a diagnostic (error or warning, as its code says); the notes that follow attach to it.
  void error(DiagCode code, SourceSpan span, std::string message) {
    last_ = &sink.report(code, span, std::move(message));
  }
  void note(SourceSpan span, std::string message) {
    if (last_) last_->notes.push_back(DiagNote{span, true, std::move(message)});
  }
  void note(std::string message) {  // a note without a place
    if (last_) last_->notes.push_back(DiagNote{SourceSpan{}, false, std::move(message)});
  }

 private:
  Diagnostic* last_ = nullptr;  // valid until the next report
};

// The passes, in the order check.cpp runs them.
void check_declarations(CheckContext& cx);  // check_names.cpp: duplicates, constant values
void check_lsystem(CheckContext& cx, std::uint32_t file, const ast::LSystem& ls);
void check_lsystem_flow(CheckContext& cx, std::uint32_t file, const ast::LSystem& ls);
void check_brackets(CheckContext& cx, const ast::LSystem& ls);  // check_brackets.cpp
void check_pieces(CheckContext& cx, std::uint32_t file, const ast::Pieces& ps);
void check_voxels(CheckContext& cx, std::uint32_t file, const ast::Voxels& vx);
void check_unused_constants(CheckContext& cx);  // check_names.cpp

// Module names (check_modules.cpp): a name as written stands for one module (a turtle symbol,
// a declared name, a single letter) or, undeclared and made of letters only, one module per
// letter (docs/language.md). Empty when it must be declared (digits or underscores).
struct ModuleRef {
  std::string name;
  std::size_t arity;
};
bool is_turtle_symbol(std::string_view name);
std::vector<std::string> module_parts(const CheckContext& cx, std::uint32_t file,
                                      std::string_view name);

std::string plural(std::size_t n, std::string_view word);  // "1 argument", "2 arguments"

}  // namespace ramus::detail
