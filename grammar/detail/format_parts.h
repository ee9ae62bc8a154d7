// The formatter's one-line pieces: expressions, module sequences and patterns, and the text of
// each declaration or block item without comments. format.cpp arranges them into lines.
#pragma once

#include <string>
#include <vector>

#include "grammar/ast.h"

namespace ramus::detail {

std::string fmt_expr(const ast::Expr& e);
// The text of each module of a sequence; join them with append_module.
std::vector<std::string> fmt_modules(const ast::ModuleSeq& seq);
void append_module(std::string& out, const std::string& module_text);
std::string fmt_pattern_seq(const std::vector<ast::ModulePattern>& seq);
std::string fmt_pattern(const ast::ModulePattern& p);
std::string fmt_string(const std::string& s);  // a quoted string literal with escapes

// The text of a declaration or item printed on one line (everything but blocks, axioms and
// productions), without the final newline.
std::string fmt_import(const ast::Import& d);
std::string fmt_const(const ast::ConstDecl& d);
std::string fmt_module_decl(const ast::ModuleDecl& d);
std::string fmt_setting(const ast::Setting& s);
std::string fmt_symbol_set(const ast::SymbolSet& s);
std::string fmt_select(const ast::Select& s);
// A production's text before its successors: `[kind] [left <] pred [> right] [: guard] ->`.
std::string fmt_production_head(const ast::Production& p);
std::string fmt_probability(const ast::Alternative& a);  // `(p)`, or empty when deterministic
std::string fmt_rim(const ast::RimDecl& r);
std::string fmt_piece(const ast::PieceDecl& p);
std::string fmt_attach(const ast::AttachRule& a);
std::string fmt_piece_setting(const ast::PieceSetting& s);
std::string fmt_voxel_setting(const ast::VoxelSetting& s);
std::string fmt_voxel_rule(const ast::VoxelRule& r);

}  // namespace ramus::detail
