// Branches and polygons that close nothing. A `]` with no open branch or a `}` with no open
// polygon is an error at derivation and interpretation, never skipped: `ramus check` reports the
// unbalanced successor in the source (E0309, grammar/check_brackets.cpp), and these run-time checks
// catch what reaches the engine without the checker (an .rmb, the runtime library).
#pragma once

#include <string>

#include "compiler/ir.h"
#include "compiler/module_string.h"

namespace ramus {

// True when some alternative of table `kind` writes a `]` it does not open itself, so a pass of
// that table can leave a `]` with no open branch (if none does, a balanced string stays
// balanced: the engine then skips the scan).
bool may_unbalance_branches(const ir::Grammar& g, ir::Kind kind);

// What is wrong when a `]` of `s` closes no branch, naming `where` ("step 3", "the axiom") and
// the productions of `kind` that write an unmatched `]`; empty when every `]` closes a branch.
// (The engine throws it as a DeriveError.)
std::string unclosed_branch_error(const ir::Grammar& g, const ModuleString& s, ir::Kind kind,
                                  const std::string& where);

// " -- written by production `...` (file:line:col)" for the productions (of any kind) whose
// successor holds an unmatched closing `symbol` (`]` or `}`); empty when none does.
std::string unbalanced_productions(const ir::Grammar& g, ir::SymbolId symbol);

}  // namespace ramus
