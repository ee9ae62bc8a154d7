#include "compiler/expr_compile.h"

#include <algorithm>
#include <optional>
#include <string>

#include "compiler/expr_vm.h"
#include "grammar/builtins.h"

namespace ramus {

namespace {

class Emitter {
 public:
  Emitter(ir::Grammar& g, const ExprScope& scope) : g_(g), scope_(scope) {}

  void expr(const ast::Expr& e) {
    std::visit([&](const auto& n) { node(n, e.span); }, e.node);
  }
  bool loads = false, random = false;
  int depth = 0, max_depth = 0;

 private:
  void emit(ir::Op op, std::uint32_t a, int delta) {
    g_.code.push_back(ir::Instr{op, a});
    depth += delta;
    max_depth = std::max(max_depth, depth);
  }
  void push_const(double v) {
    g_.consts.push_back(v);
    emit(ir::Op::Const, std::uint32_t(g_.consts.size() - 1), +1);
  }
  std::uint32_t here() const { return std::uint32_t(g_.code.size()); }
  void patch(std::uint32_t at) { g_.code[at].a = here(); }

  void node(const ast::NumberLit& n, SourceSpan) { push_const(n.value); }
  void node(const ast::BoolLit& b, SourceSpan) { push_const(b.value ? 1.0 : 0.0); }
  // A name is a parameter (its slot) or else a constant: the scope's, then a named one (pi, ...).
  std::optional<std::uint32_t> param_slot(const std::string& name) const {
    for (const auto& [n, slot] : scope_.params) {
      if (n == name) return slot;
    }
    return std::nullopt;
  }
  bool constant_named(const std::string& name, double& v) const {
    if (param_slot(name)) return false;
    if (scope_.constants) {
      for (const ir::Constant& c : *scope_.constants) {
        if (c.name == name) return v = c.value, true;
      }
    }
    return find_named_constant(name, v);
  }
  void node(const ast::NameRef& r, SourceSpan span) {
    if (const std::optional<std::uint32_t> slot = param_slot(r.name)) {
      loads = true;
      emit(ir::Op::Load, *slot, +1);
      return;
    }
    double v = 0;
    if (constant_named(r.name, v)) return push_const(v);
    throw CompileError("unknown name '" + r.name + "'", span);
  }
  // The value of `e` when it is a constant by itself: a literal, a named constant (not shadowed
  // by a parameter), or one of those under unary + and -.
  bool constant_value(const ast::Expr& e, double& v) const {
    if (const auto* n = std::get_if<ast::NumberLit>(&e.node)) return v = n->value, true;
    if (const auto* u = std::get_if<ast::Unary>(&e.node)) {
      if (u->op == ast::UnaryOp::Not || !constant_value(*u->operand, v)) return false;
      if (u->op == ast::UnaryOp::Neg) v = -v;
      return true;
    }
    const auto* r = std::get_if<ast::NameRef>(&e.node);
    return r && constant_named(r->name, v);
  }
  void node(const ast::Unary& u, SourceSpan) {
    // A negated constant is one constant, as a negative named constant is: `l * -30`, `l * -pi`
    // and `l * a2` with `const a2 = -30` compile to a constant each (the decompiler prints
    // constants as literals, `-3.14...` for -pi, so a .rmb decompiles and compiles back to the
    // code it holds).
    if (double v = 0; u.op == ast::UnaryOp::Neg && constant_value(*u.operand, v)) {
      return push_const(-v);
    }
    expr(*u.operand);
    if (u.op == ast::UnaryOp::Neg) emit(ir::Op::Neg, 0, 0);
    if (u.op == ast::UnaryOp::Not) emit(ir::Op::Not, 0, 0);
  }
  // && and || short-circuit, so `x != 0 && 1 / x > 2` never divides by zero.
  void logical(const ast::Binary& b) {
    const bool is_and = b.op == ast::BinaryOp::And;
    expr(*b.lhs);
    std::uint32_t j1 = here();
    emit(ir::Op::JumpIfFalse, 0, -1);
    if (is_and) {
      expr(*b.rhs);
      push_const(0);
      emit(ir::Op::Ne, 0, -1);
      std::uint32_t j2 = here();
      emit(ir::Op::Jump, 0, 0);
      patch(j1);
      --depth;  // the other path pushes its own value
      push_const(0);
      patch(j2);
    } else {
      push_const(1);
      std::uint32_t j2 = here();
      emit(ir::Op::Jump, 0, 0);
      patch(j1);
      --depth;
      expr(*b.rhs);
      push_const(0);
      emit(ir::Op::Ne, 0, -1);
      patch(j2);
    }
  }
  void node(const ast::Binary& b, SourceSpan) {
    if (b.op == ast::BinaryOp::And || b.op == ast::BinaryOp::Or) return logical(b);
    expr(*b.lhs);
    expr(*b.rhs);
    static constexpr ir::Op ops[] = {
        ir::Op::Or, ir::Op::And, ir::Op::Eq,  ir::Op::Ne,  ir::Op::Lt,  ir::Op::Le,  ir::Op::Gt,
        ir::Op::Ge, ir::Op::Add, ir::Op::Sub, ir::Op::Mul, ir::Op::Div, ir::Op::Mod, ir::Op::Pow};
    emit(ops[int(b.op)], 0, -1);
  }
  void node(const ast::Conditional& c, SourceSpan) {
    expr(*c.cond);
    std::uint32_t j1 = here();
    emit(ir::Op::JumpIfFalse, 0, -1);
    expr(*c.then_expr);
    std::uint32_t j2 = here();
    emit(ir::Op::Jump, 0, 0);
    patch(j1);
    --depth;
    expr(*c.else_expr);
    patch(j2);
  }
  void node(const ast::Call& c, SourceSpan span) {
    const BuiltinInfo* b = find_builtin(c.callee.name);
    if (!b) throw CompileError("unknown function '" + c.callee.name + "'", span);
    if (c.args.size() != b->arity) {
      throw CompileError("'" + c.callee.name + "' takes " + std::to_string(b->arity) +
                             " argument(s), got " + std::to_string(c.args.size()),
                         span);
    }
    if (b->random && !scope_.allow_random) {
      throw CompileError("'" + c.callee.name + "' draws random numbers and cannot be used here",
                         span);
    }
    for (const auto& a : c.args) expr(a);
    random = random || b->random;
    emit(ir::Op::Call, std::uint32_t(b - kBuiltins), 1 - int(b->arity));
  }

  ir::Grammar& g_;
  const ExprScope& scope_;
};

ir::CodeId finish(ir::Grammar& g, ir::Code code) {
  if (code.end == code.begin + 1 && g.code[code.begin].op == ir::Op::Const) {
    code.shape = ir::Code::Shape::Constant;
    code.value = g.consts[g.code[code.begin].a];
  } else if (code.end == code.begin + 1 && g.code[code.begin].op == ir::Op::Load) {
    code.shape = ir::Code::Shape::Param;
    code.slot = g.code[code.begin].a;
  } else if (code.end == code.begin + 3 && g.code[code.begin].op == ir::Op::Load &&
             g.code[code.begin + 1].op == ir::Op::Const) {
    const ir::Op op = g.code[code.begin + 2].op;
    const double k = g.consts[g.code[code.begin + 1].a];
    const bool simple = op == ir::Op::Add || op == ir::Op::Sub || op == ir::Op::Mul ||
                        (op == ir::Op::Div && k != 0);
    if (simple) {
      code.shape = ir::Code::Shape::ParamOpConst;
      code.slot = g.code[code.begin].a;
      code.value = k;
      code.op = op;
    }
  }
  g.codes.push_back(code);
  return ir::CodeId(g.codes.size() - 1);
}

}  // namespace

ir::CodeId compile_expr(ir::Grammar& g, const ast::Expr& e, const ExprScope& scope,
                        const std::string& where) {
  g.locations.push_back(where);
  ir::Code code;
  code.where = std::uint32_t(g.locations.size() - 1);
  code.begin = std::uint32_t(g.code.size());
  Emitter em(g, scope);
  em.expr(e);
  code.end = std::uint32_t(g.code.size());
  code.max_stack = std::uint16_t(std::min(em.max_depth, 65535));
  code.random = em.random;
  if (code.max_stack > 256) throw CompileError("expression nested too deeply", e.span);
  if (!em.loads && !em.random && code.end != code.begin + 1) {
    // Fold: run it once now and keep the value (errors point at the expression).
    ir::CodeId tmp = finish(g, code);
    double v = 0;
    try {
      v = eval_constant(g, tmp);
    } catch (const ExprError& err) {
      throw CompileError(err.what(), e.span);
    }
    g.codes.pop_back();
    g.code.resize(code.begin);
    g.consts.push_back(v);
    g.code.push_back(ir::Instr{ir::Op::Const, std::uint32_t(g.consts.size() - 1)});
    code.end = code.begin + 1;
    code.max_stack = 1;
  }
  return finish(g, code);
}

ir::CodeId constant_code(ir::Grammar& g, double value, const std::string& where) {
  g.locations.push_back(where);
  ir::Code code;
  code.where = std::uint32_t(g.locations.size() - 1);
  code.begin = std::uint32_t(g.code.size());
  g.consts.push_back(value);
  g.code.push_back(ir::Instr{ir::Op::Const, std::uint32_t(g.consts.size() - 1)});
  code.end = code.begin + 1;
  code.max_stack = 1;
  return finish(g, code);
}

double eval_constant(const ir::Grammar& g, ir::CodeId c) {
  LazyRng rng(0, 0, 0);
  return eval(g, c, nullptr, rng);
}

}  // namespace ramus
