#include "compiler/rmb_verify.h"

#include <iterator>
#include <string>

#include "formats/rmb/rmb_io.h"
#include "grammar/builtins.h"

namespace ramus {

namespace {

// Stack effect of one instruction: values it needs on the stack, and the depth change.
struct Effect {
  int need, delta;
};

Effect effect(const ir::Instr& in) {
  switch (in.op) {
    case ir::Op::Const:
    case ir::Op::Load:
      return {0, 1};
    case ir::Op::Neg:
    case ir::Op::Not:
      return {1, 0};
    case ir::Op::Jump:
      return {0, 0};
    case ir::Op::JumpIfFalse:
      return {1, -1};
    case ir::Op::Call: {
      const int arity = kBuiltins[in.a].arity;
      return {arity, 1 - arity};
    }
    default:
      return {2, -1};  // binary operators
  }
}

// Proves code c safe: every reachable instruction sees one consistent stack depth, within
// [need, max_stack], and the code ends with exactly one value. Jumps go forward only (the
// expression compiler emits no loops), so one pass in order sees every predecessor first.
std::string check_code(const ir::Grammar& g, const ir::Code& c) {
  const std::uint32_t n = c.end - c.begin;
  std::vector<int> depth(n + 1, -1);
  depth[0] = 0;
  auto merge = [&](std::uint32_t at, int d) {
    if (depth[at] == -1) depth[at] = d;
    return depth[at] == d;
  };
  for (std::uint32_t i = 0; i < n; ++i) {
    const ir::Instr& in = g.code[c.begin + i];
    const std::string where = "instruction " + std::to_string(c.begin + i) + ": ";
    if (depth[i] < 0) continue;  // unreachable: never executed
    if (in.op == ir::Op::Const && in.a >= g.consts.size())
      return where + "constant index out of range";
    if (in.op == ir::Op::Load && in.a >= ir::kMaxSlots) return where + "slot out of range";
    if (in.op == ir::Op::Call && in.a >= std::size(kBuiltins)) return where + "unknown builtin";
    const Effect e = effect(in);
    const int d = depth[i];
    if (d < e.need) return where + "stack underflow";
    const int after = d + e.delta;
    if (after > int(c.max_stack)) return where + "stack deeper than max_stack";
    if (in.op == ir::Op::Jump || in.op == ir::Op::JumpIfFalse) {
      if (in.a <= c.begin + i || in.a > c.end) return where + "jump outside the code or backwards";
      if (!merge(in.a - c.begin, after)) return where + "inconsistent stack depth at jump target";
    }
    if (in.op != ir::Op::Jump && !merge(i + 1, after)) return where + "inconsistent stack depth";
  }
  // Every shape keeps its bytecode: the fast paths fall back to it on a non-finite result.
  if (depth[n] != 1) return "the code does not leave exactly one value";
  return "";
}

bool reads_slots(const ir::Grammar& g, const ir::Code& c) {
  if (c.shape == ir::Code::Shape::Param || c.shape == ir::Code::Shape::ParamOpConst) return true;
  for (std::uint32_t i = c.begin; i < c.end; ++i) {
    if (g.code[i].op == ir::Op::Load) return true;
  }
  return false;
}

}  // namespace

bool rmb_has_operand(ir::Op op) {
  return op == ir::Op::Const || op == ir::Op::Load || op == ir::Op::Jump ||
         op == ir::Op::JumpIfFalse || op == ir::Op::Call;
}

void verify_rmb_codes(const ir::Grammar& g, const std::vector<std::size_t>& code_at) {
  for (std::size_t c = 0; c < g.codes.size(); ++c) {
    const std::string problem = check_code(g, g.codes[c]);
    if (!problem.empty()) {
      throw rmb::RmbError(
          code_at[c], "expected a valid expression for code " + std::to_string(c) + ": " + problem);
    }
  }
  for (const ir::SuccModule& m : g.axiom) {
    for (std::uint32_t k = 0; k < m.nargs; ++k) {
      const ir::CodeId c = g.args[m.arg_begin + k];
      if (reads_slots(g, g.codes[c])) {
        throw rmb::RmbError(code_at[c], "expected a constant axiom argument, code " +
                                            std::to_string(c) + " reads a parameter");
      }
    }
  }
}

}  // namespace ramus
