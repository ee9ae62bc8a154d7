// What the program says about a module name: its declaration, the productions that rewrite it
// and the signature an editor shows (`A(l, w)`, from the declaration, else from the first
// predecessor written with parentheses).
#pragma once

#include <string>
#include <vector>

#include "lsp/analysis.h"

namespace ramus::lsp {

// The productions (all kinds) whose predecessor is `name`, in the root file first, then imports.
std::vector<const ast::Production*> productions_of(const Analysis& analysis,
                                                   const std::string& name);

// `A(l, w)`, `A` when no pattern gives parameter names.
std::string module_signature(const Analysis& analysis, const std::string& name);

struct ModuleName {
  std::string name;
  std::string signature;  // as module_signature gives it
};

// Every module name the program declares or rewrites, and those its axioms and successors use,
// once each, in order of appearance, with their signatures (in one pass: a grammar of
// thousands of modules is completed as fast as a small one).
std::vector<ModuleName> module_names(const Analysis& analysis);

// A pattern as written: `A(l, w)`.
std::string pattern_text(const ast::ModulePattern& p);

}  // namespace ramus::lsp
