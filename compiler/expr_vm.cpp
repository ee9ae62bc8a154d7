#include "compiler/expr_vm.h"

#include <cmath>

#include "grammar/builtin_math.h"
#include "grammar/builtins.h"

namespace ramus {

namespace {

[[noreturn]] void fail(ir::CodeId c, const char* why) { throw ExprError(why, c); }

double checked(double v, ir::CodeId c, const char* why) {
  if (!std::isfinite(v)) fail(c, why);
  return v;
}

// Domain checks first, so the message names the cause rather than "not finite"; the arithmetic
// itself is the constant folder's (grammar/builtin_math.h).
double call_math(Builtin b, const double* x, ir::CodeId c, LazyRng& rng) {
  switch (b) {
    case Builtin::Tan:
      return checked(builtin_math(b, x), c, "tan of an odd multiple of 90");
    case Builtin::Asin:
      if (x[0] < -1 || x[0] > 1) fail(c, "asin of a value outside [-1, 1]");
      break;
    case Builtin::Acos:
      if (x[0] < -1 || x[0] > 1) fail(c, "acos of a value outside [-1, 1]");
      break;
    case Builtin::Sqrt:
      if (x[0] < 0) fail(c, "square root of a negative number");
      break;
    case Builtin::Exp:
      return checked(builtin_math(b, x), c, "exp overflows");
    case Builtin::Log:
    case Builtin::Log10:
      if (x[0] <= 0) fail(c, "logarithm of a number that is not positive");
      break;
    case Builtin::Pow:
      if (x[0] < 0 && x[1] != std::floor(x[1])) {
        fail(c, "power of a negative number with a fractional exponent");
      }
      if (x[0] == 0 && x[1] < 0) fail(c, "zero to a negative power");
      return checked(builtin_math(b, x), c, "power overflows");
    case Builtin::Clamp:
      if (x[1] > x[2]) fail(c, "clamp with lower bound above upper bound");
      break;
    case Builtin::Uniform:
      return rng.get().uniform(x[0], x[1]);
    case Builtin::Normal:
      if (x[1] < 0) fail(c, "normal with a negative standard deviation");
      return rng.get().normal(x[0], x[1]);
    default:
      break;
  }
  return builtin_math(b, x);
}

double modulo(double a, double b, ir::CodeId c) {
  if (b == 0) fail(c, "modulo by zero");
  return std::fmod(a, b);
}

}  // namespace

double run_code(const ir::Grammar& g, ir::CodeId c, const double* slots, LazyRng& rng) {
  const ir::Code& code = g.codes[c];
  double stack[256];
  if (code.max_stack > 256) fail(c, "expression too deep");
  int sp = 0;  // number of values on the stack
  const ir::Instr* prog = g.code.data();
  for (std::uint32_t pc = code.begin; pc < code.end;) {
    const ir::Instr in = prog[pc++];
    switch (in.op) {
      case ir::Op::Const:
        stack[sp++] = g.consts[in.a];
        break;
      case ir::Op::Load:
        stack[sp++] = slots[in.a];
        break;
      case ir::Op::Neg:
        stack[sp - 1] = -stack[sp - 1];
        break;
      case ir::Op::Not:
        stack[sp - 1] = stack[sp - 1] == 0 ? 1.0 : 0.0;
        break;
      case ir::Op::Jump:
        pc = in.a;
        break;
      case ir::Op::JumpIfFalse:
        if (stack[--sp] == 0) pc = in.a;
        break;
      case ir::Op::Call: {
        const BuiltinInfo& b = kBuiltins[in.a];
        sp -= b.arity;
        stack[sp] = call_math(b.id, stack + sp, c, rng);
        ++sp;
        break;
      }
      default: {
        const double y = stack[--sp];
        double& x = stack[sp - 1];
        switch (in.op) {
          case ir::Op::Add:
            x = checked(x + y, c, "addition overflows");
            break;
          case ir::Op::Sub:
            x = checked(x - y, c, "subtraction overflows");
            break;
          case ir::Op::Mul:
            x = checked(x * y, c, "multiplication overflows");
            break;
          case ir::Op::Div:
            if (y == 0) fail(c, "division by zero");
            x = checked(x / y, c, "division overflows");
            break;
          case ir::Op::Mod:
            x = modulo(x, y, c);
            break;
          case ir::Op::Pow: {
            const double a[2] = {x, y};
            x = call_math(Builtin::Pow, a, c, rng);
            break;
          }
          case ir::Op::Eq:
            x = x == y;
            break;
          case ir::Op::Ne:
            x = x != y;
            break;
          case ir::Op::Lt:
            x = x < y;
            break;
          case ir::Op::Le:
            x = x <= y;
            break;
          case ir::Op::Gt:
            x = x > y;
            break;
          case ir::Op::Ge:
            x = x >= y;
            break;
          case ir::Op::And:
            x = (x != 0 && y != 0);
            break;
          case ir::Op::Or:
            x = (x != 0 || y != 0);
            break;
          default:
            fail(c, "invalid instruction");
        }
      }
    }
  }
  if (sp != 1) fail(c, "invalid bytecode (stack imbalance)");
  return checked(stack[0], c, "result is not finite");
}

}  // namespace ramus
