// The rule definitions of the ramus grammar (docs/language.md). Each rule carries the EBNF
// production it parses as a comment. Rules build the AST in semantic actions; the rules of
// nodes with a SourceSpan wrap their body in spanned().
//
// Contextual keywords: a keyword is matched as a whole word only where the grammar expects one;
// block items try the keyword-free production first, so `param seed = 1;` and a module called
// `axiom` both parse. Expectation points (`>`) sit only where the item is already committed,
// so a failed one is a real syntax error ("expected X") and never cuts off an alternative.
#pragma once

#include <boost/fusion/include/at_c.hpp>
#include <boost/optional.hpp>
#include <charconv>
#include <cmath>
#include <string>

#include "grammar/detail/rules.h"

// A parser with a semantic action describes itself as its subject does, so an expectation on
// `identifier[...]` reads "expected identifier" rather than a type name.
namespace boost::spirit::x3 {
template <typename Subject, typename Action>
struct get_info<action<Subject, Action>> {
  typedef std::string result_type;
  std::string operator()(action<Subject, Action> const& p) const { return what(p.subject); }
};
}  // namespace boost::spirit::x3

namespace ramus::parser {

using boost::fusion::at_c;
using x3::_attr;
using x3::_val;
using x3::char_;
using x3::eoi;
using x3::lexeme;
using x3::lit;
using x3::raw;

// ---- helpers ------------------------------------------------------------------------------------

template <typename Ctx>
ParseState& state(Ctx const& ctx) {
  return x3::get<state_tag>(ctx).get();
}

// Sets the node's span: from after the leading trivia to the end of the last token. (X3's
// on_success would see no attribute in rules with semantic actions, so the span is taken by two
// zero-width parsers: `eps` skips the trivia before the node, `no_skip[eps]` stays where the
// node ended; an action sees the position after its parser as _where(c).begin().)
template <typename Node>
SourceSpan& span_of(Node& node) {
  if constexpr (requires { node.e.span; }) {
    return node.e.span;
  } else {
    return node.span;
  }
}
inline auto const span_begin = [](auto& c) {
  span_of(_val(c)) = state(c).span(x3::_where(c).begin(), x3::_where(c).begin());
};
inline auto const span_end = [](auto& c) {
  span_of(_val(c)).end = state(c).span(x3::_where(c).begin(), x3::_where(c).begin()).end;
};
template <typename Body>
auto spanned(Body const& body) {
  return x3::eps[span_begin] >> body >> x3::no_skip[x3::eps][span_end];
}

// Bounds X3's recursion: every nested expression passes here (see NestingError).
template <typename Subject>
struct depth_guard_directive : x3::unary_parser<Subject, depth_guard_directive<Subject>> {
  using base_type = x3::unary_parser<Subject, depth_guard_directive<Subject>>;
  static bool const is_pass_through_unary = true;
  static bool const handles_container = Subject::handles_container;
  constexpr depth_guard_directive(Subject const& subject) : base_type(subject) {}

  template <typename It, typename Ctx, typename RCtx, typename Attr>
  bool parse(It& first, It const& last, Ctx const& ctx, RCtx& rctx, Attr& attr) const {
    ParseState& st = state(ctx);
    if (st.depth >= detail::kMaxNesting) throw NestingError{first};
    ++st.depth;
    struct Leave {
      int& depth;
      ~Leave() { --depth; }
    } leave{st.depth};
    return this->subject.parse(first, last, ctx, rctx, attr);
  }
};
struct depth_guard_gen {
  template <typename Subject>
  constexpr depth_guard_directive<typename x3::extension::as_parser<Subject>::value_type>
  operator[](Subject const& subject) const {
    return {x3::as_parser(subject)};
  }
};
inline constexpr depth_guard_gen depth_guard{};

template <typename T>
std::vector<T> take(std::vector<T>& v) {
  return std::move(v);
}
template <typename T>
std::vector<T> take(boost::optional<std::vector<T>>& v) {
  return v ? std::move(*v) : std::vector<T>{};
}

inline PExpr finish(PExpr e, std::uint32_t depth, ParseState& st) {
  e.depth = depth;
  if (depth > std::uint32_t(detail::kMaxNesting)) throw NestingError{st.base + e.e.span.begin};
  return e;
}
inline PExpr make_binary(ast::BinaryOp op, PExpr lhs, PExpr rhs, ParseState& st) {
  PExpr r;
  r.e.span = {lhs.e.span.file, lhs.e.span.begin, rhs.e.span.end};
  std::uint32_t depth = 1 + std::max(lhs.depth, rhs.depth);
  r.e.node = ast::Binary{op, std::move(lhs.e), std::move(rhs.e)};
  return finish(std::move(r), depth, st);
}
inline PExpr make_unary(const PrefixOp& op, PExpr operand, ParseState& st) {
  PExpr r;
  r.e.span = {op.span.file, op.span.begin, operand.e.span.end};
  std::uint32_t depth = 1 + operand.depth;
  r.e.node = ast::Unary{op.op, std::move(operand.e)};
  return finish(std::move(r), depth, st);
}
inline PExpr apply_prefixes(std::vector<PrefixOp>& ops, PExpr e, ParseState& st) {
  for (std::size_t i = ops.size(); i-- > 0;) e = make_unary(ops[i], std::move(e), st);
  return e;
}

inline ast::NumberLit make_number(std::string text) {
  ast::NumberLit n;
  auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), n.value);
  if (ec == std::errc::result_out_of_range) {
    // Too large or too small for a double: infinity or zero, as strtod does.
    bool tiny = text.find("e-") != std::string::npos || text.find("E-") != std::string::npos;
    n.value = tiny ? 0.0 : HUGE_VAL;
  }
  n.text = std::move(text);
  return n;
}

// Semantic actions used in many rules.
inline auto const assign = [](auto& c) { _val(c) = std::move(_attr(c)); };
inline auto const assign_range = [](auto& c) {
  _val(c) = std::string(_attr(c).begin(), _attr(c).end());
};

// ---- rule ids -----------------------------------------------------------------------------------

struct identifier_class {};
struct primary_class {};
struct prefix_op_class {};
struct module_call_class {};
struct module_pat_class {};
struct symbol_class {};
struct alternative_class {};
struct det_alternative_class {};
struct production_class {};
struct axiom_class {};
struct symbol_set_class {};
struct select_class {};
struct setting_class {};
struct constructor_class {};
struct rim_decl_class {};
struct piece_decl_class {};
struct attach_class {};
struct piece_setting_class {};
struct voxel_rule_class {};
struct voxel_setting_class {};
struct import_class {};
struct const_decl_class {};
struct module_decl_class {};
struct block_head_class {};

// ---- lexical ------------------------------------------------------------------------------------

auto const letter = char_('a', 'z') | char_('A', 'Z') | char_('_');
auto const ident_char = letter | char_('0', '9');
auto const digits = +char_('0', '9');

inline auto kw(char const* word) { return lexeme[lit(word) >> !ident_char]; }

x3::rule<struct ident_class, std::string> const ident = "identifier";
x3::rule<identifier_class, ast::Identifier> const identifier = "identifier";
x3::rule<struct string_class, std::string> const string_lit = "string";
x3::rule<struct escape_class, char> const escape = "escape sequence";
x3::rule<struct number_class, ast::NumberLit> const number = "number";

// ident = letter { letter | digit } ;   letter = "A".."Z" | "a".."z" | "_" ;
auto const ident_def = lexeme[letter >> *ident_char];
auto const identifier_def = spanned(ident[([](auto& c) { _val(c).name = std::move(_attr(c)); })]);
// string = '"' { char | '\"' | '\\' } '"' ;   (on one line)
auto const escape_def = char_('"') | char_('\\');
auto const string_lit_def =
    lexeme[lit('"') > *((lit('\\') > escape) | (char_ - '"' - '\\' - '\n')) > lit('"')];
// number = ( digits [ "." { digit } ] | "." digits ) [ ( "e" | "E" ) [ "+" | "-" ] digits ] ;
auto const number_def =
    raw[lexeme[(digits >> -(lit('.') >> *char_('0', '9')) | (lit('.') >> digits)) >>
               -((lit('e') | lit('E')) >> -(lit('+') | lit('-')) >> digits)]]
       [([](auto& c) { _val(c) = make_number(std::string(_attr(c).begin(), _attr(c).end())); })];

BOOST_SPIRIT_DEFINE(ident, identifier, escape, string_lit, number)

// ---- expressions --------------------------------------------------------------------------------

x3::rule<struct pexpr_class, PExpr> const pexpr = "expression";
x3::rule<struct cond_class, PExpr> const cond_expr = "expression";
x3::rule<struct binary_class, PExpr> const binary_expr = "expression";
x3::rule<struct unary_class, PExpr> const unary_expr = "expression";
x3::rule<struct power_class, PExpr> const power_expr = "expression";
x3::rule<struct pow_operand_class, PowOperand> const pow_operand = "expression";
x3::rule<prefix_op_class, PrefixOp> const prefix_op = "unary operator";
x3::rule<primary_class, PExpr> const primary = "expression";
x3::rule<struct call_args_class, std::vector<PExpr>> const call_args = "arguments";
x3::rule<struct expr_class, ast::Expr> const expr = "expression";

// Every binary operator but `^`, with its precedence (loosest first, as in docs/language.md);
// all are left associative. One table and one loop instead of a rule per level keeps X3's
// recursion per nesting level (and so the stack a nested expression needs) small.
struct binary_ops_t : x3::symbols<ast::BinaryOp> {
  binary_ops_t() {
    using B = ast::BinaryOp;
    add("||", B::Or)("&&", B::And)("==", B::Eq)("!=", B::Ne)("<", B::Lt)("<=", B::Le)(">", B::Gt)(
        ">=", B::Ge)("+", B::Add)("-", B::Sub)("*", B::Mul)("/", B::Div)("%", B::Mod);
  }
} const binary_ops;

inline int precedence(ast::BinaryOp op) {
  using B = ast::BinaryOp;
  switch (op) {
    case B::Or:
      return 1;
    case B::And:
      return 2;
    case B::Eq:
    case B::Ne:
      return 3;
    case B::Lt:
    case B::Le:
    case B::Gt:
    case B::Ge:
      return 4;
    case B::Add:
    case B::Sub:
      return 5;
    case B::Mul:
    case B::Div:
    case B::Mod:
      return 6;
    case B::Pow:
      return 7;
  }
  return 0;
}

// Operator precedence parsing of `operand { op operand }` (Dijkstra's shunting yard).
template <typename Rest>
PExpr build_binary(PExpr first, Rest& rest, ParseState& st) {
  std::vector<PExpr> values;
  std::vector<ast::BinaryOp> ops;
  values.push_back(std::move(first));
  auto reduce = [&] {
    PExpr rhs = std::move(values.back());
    values.pop_back();
    values.back() = make_binary(ops.back(), std::move(values.back()), std::move(rhs), st);
    ops.pop_back();
  };
  for (auto& item : rest) {
    ast::BinaryOp op = at_c<0>(item);
    while (!ops.empty() && precedence(ops.back()) >= precedence(op)) reduce();
    ops.push_back(op);
    values.push_back(std::move(at_c<1>(item)));
  }
  while (!ops.empty()) reduce();
  return std::move(values.back());
}

// expr = or_expr [ "?" expr ":" expr ] ;   (nesting bounded by depth_guard)
auto const pexpr_def = depth_guard[cond_expr];
auto const cond_expr_def =
    binary_expr[assign] >> -((lit('?') > pexpr > lit(':') > pexpr)[([](auto& c) {
      auto& a = _attr(c);
      PExpr r;
      r.e.span = {_val(c).e.span.file, _val(c).e.span.begin, at_c<1>(a).e.span.end};
      std::uint32_t d = 1 + std::max({_val(c).depth, at_c<0>(a).depth, at_c<1>(a).depth});
      r.e.node =
          ast::Conditional{std::move(_val(c).e), std::move(at_c<0>(a).e), std::move(at_c<1>(a).e)};
      _val(c) = finish(std::move(r), d, state(c));
    })]);
// or_expr  = and_expr { "||" and_expr } ;
// and_expr = eq_expr { "&&" eq_expr } ;
// eq_expr  = rel_expr { ( "==" | "!=" ) rel_expr } ;
// rel_expr = add_expr { ( "<" | "<=" | ">" | ">=" ) add_expr } ;
// add_expr = mul_expr { ( "+" | "-" ) mul_expr } ;
// mul_expr = unary { ( "*" | "/" | "%" ) unary } ;
//   (the five levels in one loop, see build_binary; the "-" of "->" is never minus)
auto const binary_expr_def =
    (unary_expr >> *(lexeme[binary_ops >> !lit('>')] > unary_expr))[([](auto& c) {
      auto& a = _attr(c);
      _val(c) = build_binary(std::move(at_c<0>(a)), at_c<1>(a), state(c));
    })];
// unary = ( "-" | "+" | "!" ) unary | power ;   (parsed as a loop, not a recursion)
auto const prefix_op_def =
    spanned(lexeme[lit('-') >> !lit('>')][([](auto& c) { _val(c).op = ast::UnaryOp::Neg; })] |
            lit('+')[([](auto& c) { _val(c).op = ast::UnaryOp::Plus; })] |
            (lit('!') >> !lit('='))[([](auto& c) { _val(c).op = ast::UnaryOp::Not; })]);
auto const unary_expr_def = (*prefix_op >> power_expr)[([](auto& c) {
  auto& a = _attr(c);
  _val(c) = apply_prefixes(at_c<0>(a), std::move(at_c<1>(a)), state(c));
})];
// power = primary [ "^" unary ] ;   (right associative; a chain is parsed as a loop)
auto const pow_operand_def = (*prefix_op >> primary)[([](auto& c) {
  _val(c).prefixes = std::move(at_c<0>(_attr(c)));
  _val(c).operand = std::move(at_c<1>(_attr(c)));
})];
auto const power_expr_def = (primary >> *(lit('^') > pow_operand))[([](auto& c) {
  auto& a = _attr(c);
  PExpr base = std::move(at_c<0>(a));
  auto& rest = at_c<1>(a);
  if (rest.empty()) {
    _val(c) = std::move(base);
    return;
  }
  ParseState& st = state(c);
  PExpr acc = apply_prefixes(rest.back().prefixes, std::move(rest.back().operand), st);
  for (std::size_t i = rest.size() - 1; i-- > 0;) {
    acc = make_binary(ast::BinaryOp::Pow, std::move(rest[i].operand), std::move(acc), st);
    acc = apply_prefixes(rest[i].prefixes, std::move(acc), st);
  }
  _val(c) = make_binary(ast::BinaryOp::Pow, std::move(base), std::move(acc), st);
})];
// primary = number | "true" | "false" | ident [ "(" [ expr { "," expr } ] ")" ] | "(" expr ")" ;
auto const call_args_def = lit('(') > -(pexpr % ',') > lit(')');
auto const primary_def =
    spanned(number[([](auto& c) { _val(c).e.node = std::move(_attr(c)); })] |
            kw("true")[([](auto& c) { _val(c).e.node = ast::BoolLit{true}; })] |
            kw("false")[([](auto& c) { _val(c).e.node = ast::BoolLit{false}; })] |
            (identifier >> -call_args)[([](auto& c) {
              auto& a = _attr(c);
              auto& args = at_c<1>(a);
              if (!args) {
                _val(c).e.node = ast::NameRef{std::move(at_c<0>(a).name)};
                return;
              }
              _val(c).e.span = at_c<0>(a).span;  // for the position of a nesting error
              ast::Call call{std::move(at_c<0>(a)), {}};
              std::uint32_t depth = 0;
              for (PExpr& arg : *args) {
                depth = std::max(depth, arg.depth);
                call.args.push_back(std::move(arg.e));
              }
              _val(c).e.node = std::move(call);
              _val(c) = finish(std::move(_val(c)), depth + 1, state(c));
            })] |
            (lit('(') > pexpr > lit(')'))[([](auto& c) {
              std::uint32_t begin = _val(c).e.span.begin;  // the span includes the parentheses
              _val(c) = std::move(_attr(c));
              _val(c).e.span.begin = begin;
              _val(c).e.parenthesized = true;
            })]);
auto const expr_def = pexpr[([](auto& c) { _val(c) = std::move(_attr(c).e); })];

BOOST_SPIRIT_DEFINE(pexpr, cond_expr, binary_expr, unary_expr, power_expr, pow_operand, prefix_op,
                    primary, call_args, expr)

// ---- modules ------------------------------------------------------------------------------------

x3::rule<struct module_name_class, std::string> const module_name = "module name";
x3::rule<struct call_exprs_class, std::vector<ast::Expr>> const call_exprs = "arguments";
x3::rule<module_call_class, ast::ModuleCall> const module_call = "module";
x3::rule<struct module_seq_class, ast::ModuleSeq> const module_seq = "modules";
x3::rule<struct pat_params_class, std::vector<ast::Identifier>> const pat_params = "parameters";
x3::rule<module_pat_class, ast::ModulePattern> const module_pat = "module";
x3::rule<struct pattern_seq_class, std::vector<ast::ModulePattern>> const pattern_seq = "modules";

// module_name = ident | "+" | "-" | "&" | "^" | "\" | "/" | "|" | "$" | "[" | "]"
//             | "!" | "'" | "~" | "%" | "{" | "." | "}" ;
// (`-` directly followed by `>` is the arrow; `|` followed by `(` separates alternatives; a `}`
// followed by the end of the file or a declaration keyword closes the block, so that a missing
// `;` before the block's `}` is still reported as one -- the polygon `}` of ABOP 5.2 is always
// followed by more modules or the production's `;`)
auto const decl_keyword = kw("lsystem") | kw("pieces") | kw("voxels") | kw("import") | kw("const") |
                          kw("param") | kw("module");
auto const module_name_def = ident[assign] | raw[char_("+&^\\/$[]!'~%{.")][assign_range] |
                             raw[lexeme[lit('-') >> !lit('>')]][assign_range] |
                             (lit('|') >> !lit('('))[([](auto& c) { _val(c) = "|"; })] |
                             (lit('}') >> !(eoi | decl_keyword))[([](auto& c) { _val(c) = "}"; })];
// module_call = module_name [ "(" [ expr { "," expr } ] ")" ] ;
auto const call_exprs_def = lit('(') > -(expr % ',') > lit(')');
auto const module_call_def = spanned(
    module_name[([](auto& c) { _val(c).name = std::move(_attr(c)); })] >> -call_exprs[([](auto& c) {
      _val(c).args = std::move(_attr(c));
      _val(c).has_parens = true;
    })]);
// module_seq = { module_call } ;
auto const module_seq_def = *module_call;
// module_pat = module_name [ "(" [ ident { "," ident } ] ")" ] ;
auto const pat_params_def = lit('(') >> -(identifier % ',') >> lit(')');
auto const module_pat_def = spanned(
    module_name[([](auto& c) { _val(c).name = std::move(_attr(c)); })] >> -pat_params[([](auto& c) {
      _val(c).params = std::move(_attr(c));
      _val(c).has_parens = true;
    })]);
// pattern_seq = module_pat { module_pat } ;
auto const pattern_seq_def = +module_pat;

BOOST_SPIRIT_DEFINE(module_name, call_exprs, module_call, module_seq, pat_params, module_pat,
                    pattern_seq)

// ---- lsystem items ------------------------------------------------------------------------------

x3::rule<alternative_class, ast::Alternative> const alternative = "alternative";
x3::rule<det_alternative_class, ast::Alternative> const det_alternative = "successor";
x3::rule<struct successors_class, std::vector<ast::Alternative>> const successors = "successor";
x3::rule<production_class, ast::Production> const production = "production";
x3::rule<axiom_class, ast::Axiom> const axiom = "axiom";
x3::rule<symbol_class, ast::Identifier> const symbol = "module name";
x3::rule<struct symbols_class, std::vector<ast::Identifier>> const symbols = "module name";
x3::rule<symbol_set_class, ast::SymbolSet> const symbol_set = "ignore or consider";
x3::rule<select_class, ast::Select> const select = "select";
x3::rule<struct exprs_class, std::vector<ast::Expr>> const exprs = "expression";
x3::rule<setting_class, ast::Setting> const setting = "setting";
ls_item_type const ls_item_rule = "production or setting";

// alternative = "(" expr ")" module_seq ;
auto const alternative_def = spanned(
    (lit('(') > expr > lit(')'))[([](auto& c) { _val(c).probability = std::move(_attr(c)); })] >>
    module_seq[([](auto& c) { _val(c).successor = std::move(_attr(c)); })]);
auto const det_alternative_def =
    spanned(module_seq[([](auto& c) { _val(c).successor = std::move(_attr(c)); })]);
// successors = module_seq | alternative { "|" alternative } ;
auto const successors_def =
    (alternative % '|')[assign] |
    det_alternative[([](auto& c) { _val(c).push_back(std::move(_attr(c))); })];
// production = [ "interpret" | "decompose" ] [ pattern_seq "<" ] module_pat
//              [ ">" pattern_seq ] [ ":" expr ] [ "@" "(" expr { "," expr } ")" ]
//              "->" successors ";" ;
auto const kind_stop = lit("->") | lit('<') | lit('>') | lit(':') | lit('@') | lit('(') | lit(';');
auto const production_def = spanned(
    -((kw("interpret") >>
       !kind_stop)[([](auto& c) { _val(c).kind = ast::ProductionKind::Interpret; })] |
      (kw("decompose") >>
       !kind_stop)[([](auto& c) { _val(c).kind = ast::ProductionKind::Decompose; })]) >>
    -(pattern_seq >> lit('<'))[([](auto& c) { _val(c).left_context = std::move(_attr(c)); })] >>
    module_pat[([](auto& c) { _val(c).predecessor = std::move(_attr(c)); })] >>
    -(lit('>') >> pattern_seq)[([](auto& c) { _val(c).right_context = std::move(_attr(c)); })] >>
    -(lit(':') > expr)[([](auto& c) { _val(c).guard = std::move(_attr(c)); })] >>
    -(lit('@') > lit('(') > (expr % ',') >
      lit(')'))[([](auto& c) { _val(c).key = std::move(_attr(c)); })] >>
    lit("->") > successors[([](auto& c) { _val(c).alternatives = std::move(_attr(c)); })] >
    lit(';'));
// axiom = "axiom" module_seq ";" ;
auto const axiom_def = spanned(
    kw("axiom") >> module_seq[([](auto& c) { _val(c).modules = std::move(_attr(c)); })] > lit(';'));
// symbol_set = ( "ignore" | "consider" ) module_name { module_name } ";" ;
auto const symbol_def = spanned(module_name[([](auto& c) { _val(c).name = std::move(_attr(c)); })]);
auto const symbols_def = +symbol;
auto const symbol_set_def =
    spanned((kw("ignore") | kw("consider")[([](auto& c) { _val(c).consider = true; })]) >
            symbols[([](auto& c) { _val(c).symbols = std::move(_attr(c)); })] > lit(';'));
// select = "select" ident [ "(" [ expr { "," expr } ] ")" ] ";" ;
auto const select_def =
    spanned(kw("select") >> identifier[([](auto& c) { _val(c).mode = std::move(_attr(c)); })] >>
            -(lit('(') > -(expr % ',') >
              lit(')'))[([](auto& c) { _val(c).keys = take(_attr(c)); })] > lit(';'));
// setting = ident expr { "," expr } ";" ;
auto const exprs_def = expr % ',';
auto const setting_def =
    spanned(identifier[([](auto& c) { _val(c).key = std::move(_attr(c)); })] >>
            exprs[([](auto& c) { _val(c).values = std::move(_attr(c)); })] > lit(';'));
// ls_item = production | axiom | symbol_set | select | setting ;
//   (production first: keywords are contextual, so `axiom -> F;` is a production)
auto const ls_item_rule_def =
    production[assign] | axiom[assign] | symbol_set[assign] | select[assign] | setting[assign];

BOOST_SPIRIT_DEFINE(alternative, det_alternative, successors, production, axiom, symbol, symbols,
                    symbol_set, select, exprs, setting, ls_item_rule)

// ---- pieces items -------------------------------------------------------------------------------

x3::rule<struct named_arg_class, ast::NamedArg> const named_arg = "argument";
x3::rule<struct named_args_class, std::vector<ast::NamedArg>> const named_args = "arguments";
x3::rule<constructor_class, ast::Constructor> const constructor = "piece constructor";
x3::rule<rim_decl_class, ast::RimDecl> const rim_decl = "rim";
x3::rule<piece_decl_class, ast::PieceDecl> const piece_decl = "piece";
x3::rule<struct weighted_class, ast::WeightedPiece> const weighted = "piece name";
x3::rule<struct targets_class, std::vector<ast::WeightedPiece>> const targets = "piece name";
x3::rule<attach_class, ast::AttachRule> const attach = "attach rule";
x3::rule<piece_setting_class, ast::PieceSetting> const piece_setting = "setting";
piece_item_type const piece_item_rule = "pieces item";

// named_arg = [ ident ":" ] expr ;   named_args = named_arg { "," named_arg } ;
auto const named_arg_def =
    -(identifier >> lit(':'))[([](auto& c) { _val(c).name = std::move(_attr(c)); })] >>
    expr[([](auto& c) { _val(c).value = std::move(_attr(c)); })];
auto const named_args_def = named_arg % ',';
// constructor = ident "(" [ named_args | string ] ")" ;
auto const constructor_def =
    spanned(identifier[([](auto& c) { _val(c).kind = std::move(_attr(c)); })] > lit('(') >
            -(string_lit[([](auto& c) { _val(c).path = std::move(_attr(c)); })] |
              named_args[([](auto& c) { _val(c).args = std::move(_attr(c)); })]) > lit(')'));
// "rim" ident "(" [ named_args ] ")" ";"
auto const rim_decl_def = spanned(
    kw("rim") >> identifier[([](auto& c) { _val(c).name = std::move(_attr(c)); })] >> lit('(') >
    -named_args[([](auto& c) { _val(c).args = std::move(_attr(c)); })] > lit(')') > lit(';'));
// "piece" ident "=" constructor ";"
auto const piece_decl_def = spanned(
    kw("piece") >> identifier[([](auto& c) { _val(c).name = std::move(_attr(c)); })] >> lit('=') >
    constructor[([](auto& c) { _val(c).ctor = std::move(_attr(c)); })] > lit(';'));
// weighted = ident [ expr ] ;
auto const weighted_def = identifier[([](auto& c) { _val(c).piece = std::move(_attr(c)); })] >>
                          -expr[([](auto& c) { _val(c).weight = std::move(_attr(c)); })];
auto const targets_def = weighted % '|';
// ident "." ident "->" weighted { "|" weighted } ";"
auto const attach_def =
    spanned(identifier[([](auto& c) { _val(c).piece = std::move(_attr(c)); })] >> lit('.') >>
            identifier[([](auto& c) { _val(c).rim = std::move(_attr(c)); })] >> lit("->") >
            targets[([](auto& c) { _val(c).targets = std::move(_attr(c)); })] > lit(';'));
// ident expr { "," expr } ";"   (root, twist, depth)
auto const piece_setting_def =
    spanned(identifier[([](auto& c) { _val(c).key = std::move(_attr(c)); })] >>
            exprs[([](auto& c) { _val(c).values = std::move(_attr(c)); })] > lit(';'));
// piece_item = attach | rim | piece | setting ;   (keyword-free attach first)
auto const piece_item_rule_def =
    attach[assign] | rim_decl[assign] | piece_decl[assign] | piece_setting[assign];

BOOST_SPIRIT_DEFINE(named_arg, named_args, constructor, rim_decl, piece_decl, weighted, targets,
                    attach, piece_setting, piece_item_rule)

// ---- voxels items -------------------------------------------------------------------------------

x3::rule<voxel_rule_class, ast::VoxelRule> const voxel_rule = "voxel rule";
x3::rule<voxel_setting_class, ast::VoxelSetting> const voxel_setting = "setting";
voxel_item_type const voxel_item_rule = "voxels item";

// expr "->" "[" { expr } "]" [ "x" expr ] ";"   (the checks require eight children)
auto const voxel_rule_def =
    spanned(expr[([](auto& c) { _val(c).parent = std::move(_attr(c)); })] >> lit("->") > lit('[') >
            (*expr)[([](auto& c) { _val(c).children = std::move(_attr(c)); })] > lit(']') >
            -(lit('x') > expr)[([](auto& c) { _val(c).weight = std::move(_attr(c)); })] > lit(';'));
// ident ( string | expr { "," expr } ) ";"   (levels, classes, axiom, seed)
auto const voxel_setting_def =
    spanned(identifier[([](auto& c) { _val(c).key = std::move(_attr(c)); })] >>
            (string_lit[([](auto& c) { _val(c).path = std::move(_attr(c)); })] |
             exprs[([](auto& c) { _val(c).values = std::move(_attr(c)); })]) > lit(';'));
auto const voxel_item_rule_def = voxel_rule[assign] | voxel_setting[assign];

BOOST_SPIRIT_DEFINE(voxel_rule, voxel_setting, voxel_item_rule)

// ---- file level ---------------------------------------------------------------------------------

x3::rule<import_class, ast::Import> const import_decl = "import";
x3::rule<struct import_target_class, ast::Import> const import_target = "module path or string";
x3::rule<struct binding_class, ast::Binding> const binding = "binding";
x3::rule<struct bindings_class, std::vector<ast::Binding>> const bindings = "binding";
x3::rule<const_decl_class, ast::ConstDecl> const const_decl = "constant";
x3::rule<struct module_pats_class, std::vector<ast::ModulePattern>> const module_pats = "module";
x3::rule<module_decl_class, ast::ModuleDecl> const module_decl = "module declaration";
simple_decl_type const simple_decl_rule = "declaration";
block_head_type const block_head_rule = "block";

// import = "import" ( string | ident { "." ident } ) ";" ;
auto const import_target_def =
    string_lit[([](auto& c) {
      _val(c).path = std::move(_attr(c));
      _val(c).is_file = true;
    })] |
    raw[lexeme[ident >> *(lit('.') >> ident)]]
       [([](auto& c) { _val(c).path = std::string(_attr(c).begin(), _attr(c).end()); })];
auto const import_decl_def = spanned(kw("import") > import_target[([](auto& c) {
                                       _val(c).path = std::move(_attr(c).path);
                                       _val(c).is_file = _attr(c).is_file;
                                     })] > lit(';'));
// binding = ident "=" expr ;
auto const binding_def = identifier[([](auto& c) { _val(c).name = std::move(_attr(c)); })] >
                         lit('=') > expr[([](auto& c) { _val(c).value = std::move(_attr(c)); })];
auto const bindings_def = binding % ',';
// const_decl = ( "const" | "param" ) binding { "," binding } ";" ;
auto const const_decl_def =
    spanned((kw("const") | kw("param")[([](auto& c) { _val(c).is_param = true; })]) >
            bindings[([](auto& c) { _val(c).bindings = std::move(_attr(c)); })] > lit(';'));
// module_decl = "module" module_pat { "," module_pat } ";" ;
auto const module_pats_def = module_pat % ',';
auto const module_decl_def =
    spanned(kw("module") > module_pats[([](auto& c) { _val(c).modules = std::move(_attr(c)); })] >
            lit(';'));
// decl = import | const_decl | module_decl | lsystem | pieces | voxels ;
//   (the blocks are parsed by the driver: block_head, then one item at a time, so that an error
//   in one item is reported and skipped without losing the block)
auto const simple_decl_rule_def = import_decl[assign] | const_decl[assign] | module_decl[assign];
// lsystem = "lsystem" ident "{" { ls_item } "}" ;   (pieces and voxels alike)
auto const block_head_rule_def =
    spanned((kw("lsystem") | kw("pieces")[([](auto& c) { _val(c).kind = BlockKind::Pieces; })] |
             kw("voxels")[([](auto& c) { _val(c).kind = BlockKind::Voxels; })]) >
            identifier[([](auto& c) { _val(c).name = std::move(_attr(c)); })] > lit('{'));

BOOST_SPIRIT_DEFINE(import_target, import_decl, binding, bindings, const_decl, module_pats,
                    module_decl, simple_decl_rule, block_head_rule)

block_head_type const& block_head() { return block_head_rule; }
simple_decl_type const& simple_decl() { return simple_decl_rule; }
ls_item_type const& ls_item() { return ls_item_rule; }
piece_item_type const& piece_item() { return piece_item_rule; }
voxel_item_type const& voxel_item() { return voxel_item_rule; }

}  // namespace ramus::parser
