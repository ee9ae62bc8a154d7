#include "formats/rmb/rmb_verify.h"

#include <algorithm>
#include <bit>
#include <iterator>
#include <optional>
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

ir::Code rmb_implied_code(const ir::Grammar& g, std::uint32_t begin, std::uint32_t end) {
  ir::Code code;
  code.begin = begin;
  code.end = end;
  const auto op_at = [&](std::uint32_t i) { return g.code[begin + i].op; };
  const auto const_at = [&](std::uint32_t i) -> std::optional<double> {
    const std::uint32_t a = g.code[begin + i].a;
    return a < g.consts.size() ? std::optional<double>(g.consts[a]) : std::nullopt;
  };
  const std::uint32_t n = end - begin;
  // The shapes of finish() in compiler/expr_compile.cpp.
  if (n == 1 && op_at(0) == ir::Op::Const && const_at(0)) {
    code.shape = ir::Code::Shape::Constant;
    code.value = *const_at(0);
  } else if (n == 1 && op_at(0) == ir::Op::Load && g.code[begin].a < ir::kMaxSlots) {
    code.shape = ir::Code::Shape::Param;
    code.slot = g.code[begin].a;
  } else if (n == 3 && op_at(0) == ir::Op::Load && g.code[begin].a < ir::kMaxSlots &&
             op_at(1) == ir::Op::Const && const_at(1)) {
    const ir::Op op = op_at(2);
    const double k = *const_at(1);
    if (op == ir::Op::Add || op == ir::Op::Sub || op == ir::Op::Mul ||
        (op == ir::Op::Div && k != 0)) {
      code.shape = ir::Code::Shape::ParamOpConst;
      code.slot = g.code[begin].a;
      code.value = k;
      code.op = op;
    }
  }
  // Stack depth along the code, as check_code follows it; the deepest value left.
  std::vector<int> depth(n + 1, -1);
  depth[0] = 0;
  int deepest = 0;
  bool ok = true;
  for (std::uint32_t i = 0; i < n && ok; ++i) {
    const ir::Instr& in = g.code[begin + i];
    if (in.op == ir::Op::Call && in.a < std::size(kBuiltins) && kBuiltins[in.a].random) {
      code.random = true;
    }
    if (depth[i] < 0) continue;
    if (in.op == ir::Op::Call && in.a >= std::size(kBuiltins)) {
      ok = false;
      break;
    }
    const int after = depth[i] + effect(in).delta;
    deepest = std::max(deepest, after);
    auto merge = [&](std::uint32_t at) {
      if (depth[at] == -1) depth[at] = after;
      ok = ok && depth[at] == after;
    };
    if (in.op == ir::Op::Jump || in.op == ir::Op::JumpIfFalse) {
      if (in.a <= begin + i || in.a > end) {
        ok = false;
        break;
      }
      merge(in.a - begin);
    }
    if (in.op != ir::Op::Jump) merge(i + 1);
  }
  code.max_stack = ok ? std::uint16_t(std::min(deepest, 0xFFFF)) : 0xFFFF;
  return code;
}

bool rmb_code_is_implied(const ir::Grammar& g, const ir::Code& c) {
  if (c.begin > c.end || c.end > g.code.size()) return false;
  const ir::Code i = rmb_implied_code(g, c.begin, c.end);
  return i.shape == c.shape && i.random == c.random && i.max_stack == c.max_stack &&
         std::bit_cast<std::uint64_t>(i.value) == std::bit_cast<std::uint64_t>(c.value) &&
         i.slot == c.slot && i.op == c.op;
}

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
