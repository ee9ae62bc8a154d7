// The X3 grammar of docs/language.md: rule declarations, the parse state every rule reaches
// through the context, and the attribute types the expression rules use internally. Included
// only by grammar/parser.cpp (the one translation unit that instantiates the grammar, as in X3's
// rexpr_full example); the rest of the project sees grammar/parser.h.
#pragma once

#include <boost/spirit/home/x3.hpp>
#include <cstdint>
#include <utility>
#include <vector>

#include "grammar/ast.h"
#include "grammar/detail/scan.h"

namespace ramus::parser {

namespace x3 = boost::spirit::x3;
using iterator_type = const char*;

// What the rules need from the driver: the text's base (spans are byte offsets from it), the
// file index, and the current expression nesting (X3 recursion is bounded by it).
struct ParseState {
  const char* base = nullptr;
  std::uint32_t file = 0;
  int depth = 0;
  SourceSpan span(const char* b, const char* e) const {
    return {file, std::uint32_t(b - base), std::uint32_t(e - base)};
  }
};
struct state_tag;

// Thrown (and caught by the driver, which reports E0004) when an expression nests deeper than
// kMaxNesting, before the recursion or the AST could exhaust the stack.
struct NestingError {
  const char* where;
};

// An expression under construction, with the depth of its tree.
struct PExpr {
  ast::Expr e;
  std::uint32_t depth = 1;
};
struct PrefixOp {
  ast::UnaryOp op = ast::UnaryOp::Neg;
  SourceSpan span;
};
struct PowOperand {  // one `^ [prefixes] primary` of a power chain
  std::vector<PrefixOp> prefixes;
  PExpr operand;
};

enum class BlockKind { LSystem, Pieces, Voxels };
struct BlockHead {  // `lsystem name {` -- the items are parsed one by one by the driver
  BlockKind kind = BlockKind::LSystem;
  ast::Identifier name;
  SourceSpan span;
};

// Whitespace and comments (a custom parser: one tight loop shared with the pre-scan).
struct trivia_parser : x3::parser<trivia_parser> {
  using attribute_type = x3::unused_type;
  static bool const has_attribute = false;
  template <typename Ctx, typename RCtx, typename Attr>
  bool parse(const char*& first, const char* const& last, Ctx const&, RCtx&, Attr&) const {
    // Fast path: most tokens follow no trivia at all.
    if (first == last || (*first != ' ' && *first != '\n' && *first != '/' && *first != '\t' &&
                          *first != '\r' && *first != '\f' && *first != '\v')) {
      return false;
    }
    const char* p = detail::skip_trivia(first, last);
    if (p == first) return false;
    first = p;
    return true;
  }
};
inline constexpr trivia_parser trivia{};
using skipper_type = trivia_parser;
using phrase_context_type = x3::phrase_parse_context<skipper_type>::type;
using context_type =
    x3::context<state_tag, std::reference_wrapper<ParseState>, phrase_context_type>;

// The driver's entry points; all other rules are internal to rules_def.h.
using block_head_type = x3::rule<struct block_head_class, BlockHead>;
using simple_decl_type = x3::rule<struct simple_decl_class, ast::Decl>;
using ls_item_type = x3::rule<struct ls_item_class, ast::LSystemItem>;
using piece_item_type = x3::rule<struct piece_item_class, ast::PiecesItem>;
using voxel_item_type = x3::rule<struct voxel_item_class, ast::VoxelsItem>;

BOOST_SPIRIT_DECLARE(block_head_type, simple_decl_type, ls_item_type, piece_item_type,
                     voxel_item_type)

block_head_type const& block_head();
simple_decl_type const& simple_decl();
ls_item_type const& ls_item();
piece_item_type const& piece_item();
voxel_item_type const& voxel_item();

}  // namespace ramus::parser
