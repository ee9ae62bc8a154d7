// Verification of a decoded grammar's expressions (docs/binary-format.md, Verification): what
// the VM (compiler/expr_vm.cpp) takes on trust -- operand ranges, jump targets, stack depth --
// proved from the bytes before the grammar is used.
#pragma once

#include <cstddef>
#include <vector>

#include "compiler/ir.h"

namespace ramus {

inline constexpr std::uint32_t kRmbMaxStack = 256;  // the VM's stack (compiler/expr_vm.cpp)

// Ops followed by an operand varint in the bytecode section.
bool rmb_has_operand(ir::Op op);

// The code record a range of instructions implies (format version 2 stores only the range):
// the fast-path shape with its value, slot and op exactly as the expression compiler's
// finish() classifies them (compiler/expr_compile.cpp), `random` when it calls a random
// builtin, and max_stack the deepest stack any reachable instruction leaves (the expression
// compiler's own count). Operands are not trusted: out-of-range ones give a General shape and
// are left to verify_rmb_codes; a stack that cannot be followed gives max_stack 0xFFFF.
ir::Code rmb_implied_code(const ir::Grammar& g, std::uint32_t begin, std::uint32_t end);

// Whether `c` is exactly what rmb_implied_code gives for its range (bit for bit: a value of -0
// is not 0), so that a version-2 file may leave the record out.
bool rmb_code_is_implied(const ir::Grammar& g, const ir::Code& c);

// Throws RmbError at code_at[c] for the first code whose instructions could read outside the
// constant pool, the slots or the stack, jump outside the code, or call an unknown builtin; and
// for an axiom argument that reads a parameter (the axiom has none).
void verify_rmb_codes(const ir::Grammar& g, const std::vector<std::size_t>& code_at);

}  // namespace ramus
