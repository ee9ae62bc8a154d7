#include "grammar/const_eval.h"

#include <cmath>
#include <vector>

#include "grammar/builtin_math.h"

namespace ramus {
namespace {

// Evaluates recursively; the parser bounds expression depth (E0004), so recursion is safe.
class Folder {
 public:
  explicit Folder(const ConstLookup& lookup) : lookup_(lookup) {}

  std::optional<double> eval(const ast::Expr& e) {
    return std::visit([&](const auto& n) { return node(n, e); }, e.node);
  }
  std::optional<FoldError> error;

 private:
  std::optional<double> fail(FoldError::Kind kind, const SourceSpan& span, std::string msg) {
    if (!error) error = FoldError{kind, span, std::move(msg)};
    return std::nullopt;
  }

  std::optional<double> node(const ast::NumberLit& n, const ast::Expr&) { return n.value; }
  std::optional<double> node(const ast::BoolLit& b, const ast::Expr&) {
    return b.value ? 1.0 : 0.0;
  }
  std::optional<double> node(const ast::NameRef& n, const ast::Expr& e) {
    if (lookup_) {
      if (auto v = lookup_(n.name)) return v;
    }
    double v = 0;
    if (find_named_constant(n.name, v)) return v;
    return fail(FoldError::Kind::UnknownName, e.span, "'" + n.name + "' is not a constant");
  }
  std::optional<double> node(const ast::Unary& u, const ast::Expr&) {
    auto v = eval(*u.operand);
    if (!v) return v;
    switch (u.op) {
      case ast::UnaryOp::Neg:
        return -*v;
      case ast::UnaryOp::Plus:
        return *v;
      case ast::UnaryOp::Not:
        return *v == 0 ? 1.0 : 0.0;
    }
    return std::nullopt;
  }
  std::optional<double> node(const ast::Binary& b, const ast::Expr&) {
    auto l = eval(*b.lhs);
    if (!l) return l;
    // && and || short-circuit, so `x != 0 && 1 / x > 2` folds for x == 0.
    if (b.op == ast::BinaryOp::And && *l == 0) return 0.0;
    if (b.op == ast::BinaryOp::Or && *l != 0) return 1.0;
    auto r = eval(*b.rhs);
    if (!r) return r;
    double x = *l, y = *r;
    switch (b.op) {
      case ast::BinaryOp::Or:
      case ast::BinaryOp::And:
        return y != 0 ? 1.0 : 0.0;
      case ast::BinaryOp::Eq:
        return x == y ? 1.0 : 0.0;
      case ast::BinaryOp::Ne:
        return x != y ? 1.0 : 0.0;
      case ast::BinaryOp::Lt:
        return x < y ? 1.0 : 0.0;
      case ast::BinaryOp::Le:
        return x <= y ? 1.0 : 0.0;
      case ast::BinaryOp::Gt:
        return x > y ? 1.0 : 0.0;
      case ast::BinaryOp::Ge:
        return x >= y ? 1.0 : 0.0;
      case ast::BinaryOp::Add:
        return x + y;
      case ast::BinaryOp::Sub:
        return x - y;
      case ast::BinaryOp::Mul:
        return x * y;
      case ast::BinaryOp::Div:
        return x / y;
      case ast::BinaryOp::Mod:
        return std::fmod(x, y);
      case ast::BinaryOp::Pow:
        return std::pow(x, y);
    }
    return std::nullopt;
  }
  std::optional<double> node(const ast::Conditional& c, const ast::Expr&) {
    auto cond = eval(*c.cond);
    if (!cond) return cond;
    return eval(*cond != 0 ? *c.then_expr : *c.else_expr);
  }
  std::optional<double> node(const ast::Call& c, const ast::Expr& e) {
    const BuiltinInfo* fn = find_builtin(c.callee.name);
    if (!fn) {
      return fail(FoldError::Kind::UnknownFunction, c.callee.span,
                  "unknown function '" + c.callee.name + "'");
    }
    if (c.args.size() != fn->arity) {
      return fail(FoldError::Kind::UnknownFunction, e.span,
                  "'" + c.callee.name + "' takes " + std::to_string(fn->arity) + " arguments");
    }
    if (fn->random) {
      return fail(FoldError::Kind::Random, e.span, "'" + c.callee.name + "' draws a random number");
    }
    double args[3] = {0, 0, 0};
    for (std::size_t i = 0; i < c.args.size(); ++i) {
      auto v = eval(c.args[i]);
      if (!v) return v;
      args[i] = *v;
    }
    double r = apply_builtin(fn->id, std::span<const double>(args, c.args.size()));
    if (!std::isfinite(r)) {
      return fail(FoldError::Kind::NotFinite, e.span,
                  "'" + c.callee.name + "' gives no finite value for these arguments");
    }
    return r;
  }

  const ConstLookup& lookup_;
};

}  // namespace

double apply_builtin(Builtin fn, std::span<const double> a) { return builtin_math(fn, a.data()); }

FoldResult evaluate_constant(const ast::Expr& expr, const ConstLookup& lookup) {
  Folder f(lookup);
  FoldResult r;
  auto v = f.eval(expr);
  if (!v) {
    r.error = f.error;
    return r;
  }
  if (!std::isfinite(*v)) {
    r.error = FoldError{FoldError::Kind::NotFinite, expr.span, "the value is not a finite number"};
    return r;
  }
  r.value = v;
  return r;
}

std::optional<double> fold_constant(const ast::Expr& expr, const ConstLookup& lookup) {
  return evaluate_constant(expr, lookup).value;
}

}  // namespace ramus
