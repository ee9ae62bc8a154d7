// Expressions: names (constants, params, a production's formal parameters), calls (the table in
// grammar/builtins.h) and the two types, number and boolean (docs/language.md: arithmetic on
// booleans is an error, a condition must be boolean).
#include "grammar/builtins.h"
#include "grammar/const_eval.h"
#include "grammar/detail/check_context.h"

namespace ramus::detail {
namespace {

const char* op_text(ast::BinaryOp op) {
  switch (op) {
    case ast::BinaryOp::Or:
      return "||";
    case ast::BinaryOp::And:
      return "&&";
    case ast::BinaryOp::Eq:
      return "==";
    case ast::BinaryOp::Ne:
      return "!=";
    case ast::BinaryOp::Lt:
      return "<";
    case ast::BinaryOp::Le:
      return "<=";
    case ast::BinaryOp::Gt:
      return ">";
    case ast::BinaryOp::Ge:
      return ">=";
    case ast::BinaryOp::Add:
      return "+";
    case ast::BinaryOp::Sub:
      return "-";
    case ast::BinaryOp::Mul:
      return "*";
    case ast::BinaryOp::Div:
      return "/";
    case ast::BinaryOp::Mod:
      return "%";
    case ast::BinaryOp::Pow:
      return "^";
  }
  return "?";
}

class ExprChecker {
 public:
  ExprChecker(CheckContext& cx, const ExprEnv& env) : cx_(cx), env_(env) {}

  Type check(const ast::Expr& e) {
    return std::visit([&](const auto& n) { return node(n, e); }, e.node);
  }

 private:
  Type node(const ast::NumberLit&, const ast::Expr&) { return Type::Number; }
  Type node(const ast::BoolLit&, const ast::Expr&) { return Type::Boolean; }

  Type node(const ast::NameRef& n, const ast::Expr& e) {
    if (env_.formals && env_.formals->count(n.name)) return Type::Number;
    if (ConstInfo* c = cx_.find_const(env_.file, n.name)) {
      c->used = true;
      if (c->file == env_.file && c->order >= env_.defined_before) {
        cx_.error(DiagCode::UsedBeforeDefinition, e.span,
                  "'" + n.name + "' is used before its definition");
        cx_.note(c->binding->name.span, "'" + n.name + "' is defined here");
        return Type::Error;
      }
      return c->type;
    }
    double v = 0;
    if (find_named_constant(n.name, v) || env_.unknown_names_ok) return Type::Number;
    cx_.error(DiagCode::UnknownName, e.span, "unknown name '" + n.name + "'");
    if (env_.formals) {
      cx_.note("names here are constants, params and the parameters of the production's modules");
    } else {
      cx_.note("names here are constants and params");
    }
    return Type::Error;
  }

  Type node(const ast::Unary& u, const ast::Expr&) {
    Type t = check(*u.operand);
    if (u.op == ast::UnaryOp::Not) {
      if (t == Type::Number) {
        cx_.error(DiagCode::LogicOnNumber, u.operand->span,
                  "operator '!' needs a boolean, found a number");
      }
      return Type::Boolean;
    }
    if (t == Type::Boolean) {
      cx_.error(DiagCode::ArithmeticOnBoolean, u.operand->span,
                std::string("operator '") + (u.op == ast::UnaryOp::Neg ? "-" : "+") +
                    "' needs a number, found a boolean");
    }
    return Type::Number;
  }

  void expect(Type t, Type want, const ast::Expr& side, ast::BinaryOp op) {
    if (t == Type::Error || t == want) return;
    if (want == Type::Number) {
      cx_.error(DiagCode::ArithmeticOnBoolean, side.span,
                std::string("operator '") + op_text(op) + "' needs numbers, found a boolean");
    } else {
      cx_.error(DiagCode::LogicOnNumber, side.span,
                std::string("operator '") + op_text(op) + "' needs booleans, found a number");
    }
  }

  Type node(const ast::Binary& b, const ast::Expr&) {
    Type l = check(*b.lhs);
    Type r = check(*b.rhs);
    switch (b.op) {
      case ast::BinaryOp::Or:
      case ast::BinaryOp::And:
        expect(l, Type::Boolean, *b.lhs, b.op);
        expect(r, Type::Boolean, *b.rhs, b.op);
        return Type::Boolean;
      case ast::BinaryOp::Eq:
      case ast::BinaryOp::Ne:
        if (l != Type::Error && r != Type::Error && l != r) {
          cx_.error(DiagCode::MixedTypes, b.rhs->span,
                    std::string("operator '") + op_text(b.op) + "' compares a " +
                        (l == Type::Number ? "number" : "boolean") + " with a " +
                        (r == Type::Number ? "number" : "boolean"));
        }
        return Type::Boolean;
      case ast::BinaryOp::Lt:
      case ast::BinaryOp::Le:
      case ast::BinaryOp::Gt:
      case ast::BinaryOp::Ge:
        expect(l, Type::Number, *b.lhs, b.op);
        expect(r, Type::Number, *b.rhs, b.op);
        return Type::Boolean;
      default:
        expect(l, Type::Number, *b.lhs, b.op);
        expect(r, Type::Number, *b.rhs, b.op);
        return Type::Number;
    }
  }

  Type node(const ast::Conditional& c, const ast::Expr&) {
    if (check(*c.cond) == Type::Number) {
      cx_.error(DiagCode::ConditionNotBoolean, c.cond->span,
                "the condition of '?:' is a number, not a boolean");
    }
    Type t = check(*c.then_expr);
    Type f = check(*c.else_expr);
    if (t != Type::Error && f != Type::Error && t != f) {
      cx_.error(DiagCode::MixedTypes, c.else_expr->span,
                "the branches of '?:' have different types");
      cx_.note(c.then_expr->span,
               std::string("this branch is a ") + (t == Type::Number ? "number" : "boolean"));
      return Type::Error;
    }
    return t != Type::Error ? t : f;
  }

  Type node(const ast::Call& c, const ast::Expr& e) {
    const BuiltinInfo* fn = find_builtin(c.callee.name);
    if (!fn) {
      cx_.error(DiagCode::UnknownFunction, c.callee.span,
                "unknown function '" + c.callee.name + "'");
      cx_.note("the functions are listed in docs/language.md");
    } else if (c.args.size() != fn->arity) {
      cx_.error(DiagCode::FunctionArity, e.span,
                "'" + c.callee.name + "' takes " + plural(fn->arity, "argument") + ", found " +
                    std::to_string(c.args.size()));
    } else if (fn->random && env_.constant_context) {
      cx_.error(DiagCode::RandomInConstant, c.callee.span,
                "'" + c.callee.name + "' draws a random number and cannot be used in " +
                    env_.constant_context);
    }
    for (const ast::Expr& a : c.args) {
      if (check(a) == Type::Boolean) {
        cx_.error(DiagCode::BooleanAsNumber, a.span,
                  "the arguments of '" + c.callee.name + "' must be numbers, found a boolean");
      }
    }
    return Type::Number;
  }

  CheckContext& cx_;
  const ExprEnv& env_;
};

}  // namespace

Type CheckContext::check_expr(const ast::Expr& e, const ExprEnv& env) {
  return ExprChecker(*this, env).check(e);
}

void CheckContext::check_number(const ast::Expr& e, const ExprEnv& env, std::string_view what) {
  if (check_expr(e, env) == Type::Boolean) {
    error(DiagCode::BooleanAsNumber, e.span,
          std::string(what) + " must be a number, found a boolean");
  }
}

std::optional<double> CheckContext::fold(const ast::Expr& e, std::uint32_t file,
                                         const Formals* formals) {
  return fold_constant(e, [&](std::string_view name) -> std::optional<double> {
    std::string key(name);
    if (formals && formals->count(key)) return std::nullopt;
    if (const ConstInfo* c = find_const(file, key)) return c->value;
    return std::nullopt;
  });
}

}  // namespace ramus::detail
