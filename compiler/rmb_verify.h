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

// Throws RmbError at code_at[c] for the first code whose instructions could read outside the
// constant pool, the slots or the stack, jump outside the code, or call an unknown builtin; and
// for an axiom argument that reads a parameter (the axiom has none).
void verify_rmb_codes(const ir::Grammar& g, const std::vector<std::size_t>& code_at);

}  // namespace ramus
