// One-line pieces of the canonical layout (docs/formatting.md): spaces around binary operators,
// `, ` between arguments, module sequences written without spaces except where two names would
// merge into one (or `/` `/` into a comment), parentheses only where written or needed.
#include "grammar/detail/format_parts.h"

#include <charconv>

#include "core/number_text.h"

namespace ramus::detail {
namespace {

// Precedence levels, loosest first (docs/language.md, the expr rules).
enum Level { kTernary, kOr, kAnd, kEq, kRel, kAdd, kMul, kUnary, kPower, kPrimary };

Level level_of(ast::BinaryOp op) {
  switch (op) {
    case ast::BinaryOp::Or:
      return kOr;
    case ast::BinaryOp::And:
      return kAnd;
    case ast::BinaryOp::Eq:
    case ast::BinaryOp::Ne:
      return kEq;
    case ast::BinaryOp::Lt:
    case ast::BinaryOp::Le:
    case ast::BinaryOp::Gt:
    case ast::BinaryOp::Ge:
      return kRel;
    case ast::BinaryOp::Add:
    case ast::BinaryOp::Sub:
      return kAdd;
    case ast::BinaryOp::Mul:
    case ast::BinaryOp::Div:
    case ast::BinaryOp::Mod:
      return kMul;
    case ast::BinaryOp::Pow:
      return kPower;
  }
  return kPrimary;
}

const char* op_text(ast::BinaryOp op) {
  static const char* const kText[] = {"||", "&&", "==", "!=", "<", "<=", ">",
                                      ">=", "+",  "-",  "*",  "/", "%",  "^"};
  return kText[int(op)];
}

Level level_of(const ast::Expr& e) {
  if (std::holds_alternative<ast::Conditional>(e.node)) return kTernary;
  if (const auto* b = std::get_if<ast::Binary>(&e.node)) return level_of(b->op);
  if (std::holds_alternative<ast::Unary>(e.node)) return kUnary;
  return kPrimary;
}

std::string number_text(const ast::NumberLit& n) {
  if (!n.text.empty()) return n.text;
  return shortest_text(n.value);
}

std::string expr_at(const ast::Expr& e, Level min);

std::string args_text(const std::vector<ast::Expr>& args) {
  std::string s;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (i > 0) s += ", ";
    s += expr_at(args[i], kTernary);
  }
  return s;
}

std::string bare_expr(const ast::Expr& e) {
  struct V {
    std::string operator()(const ast::NumberLit& n) const { return number_text(n); }
    std::string operator()(const ast::BoolLit& b) const { return b.value ? "true" : "false"; }
    std::string operator()(const ast::NameRef& n) const { return n.name; }
    std::string operator()(const ast::Unary& u) const {
      const char* op = u.op == ast::UnaryOp::Neg ? "-" : u.op == ast::UnaryOp::Plus ? "+" : "!";
      return op + expr_at(*u.operand, kUnary);
    }
    std::string operator()(const ast::Binary& b) const {
      Level l = level_of(b.op);
      // Left-associative, except ^ whose left side is a primary and right side a unary.
      Level lhs = l == kPower ? kPrimary : l;
      Level rhs = l == kPower ? kUnary : Level(l + 1);
      return expr_at(*b.lhs, lhs) + " " + op_text(b.op) + " " + expr_at(*b.rhs, rhs);
    }
    std::string operator()(const ast::Conditional& c) const {
      return expr_at(*c.cond, kOr) + " ? " + expr_at(*c.then_expr, kTernary) + " : " +
             expr_at(*c.else_expr, kTernary);
    }
    std::string operator()(const ast::Call& c) const {
      return c.callee.name + "(" + args_text(c.args) + ")";
    }
  };
  return std::visit(V{}, e.node);
}

std::string expr_at(const ast::Expr& e, Level min) {
  std::string s = bare_expr(e);
  if (e.parenthesized || level_of(e) < min) return "(" + s + ")";
  return s;
}

bool is_name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

}  // namespace

// Joins the modules of a sequence: a space only where the text would otherwise read
// differently (two names merging, `//` starting a comment).
void append_module(std::string& out, const std::string& text) {
  if (!out.empty() && !text.empty()) {
    char a = out.back(), b = text.front();
    if ((is_name_char(a) && is_name_char(b)) || (a == '/' && (b == '/' || b == '*'))) {
      out += ' ';
    }
  }
  out += text;
}

namespace {

std::string named_args_text(const std::vector<ast::NamedArg>& args) {
  std::string s;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (i > 0) s += ", ";
    if (!args[i].name.name.empty()) s += args[i].name.name + ": ";
    s += expr_at(args[i].value, kTernary);
  }
  return s;
}

std::string values_text(const std::vector<ast::Expr>& values) {
  std::string s = args_text(values);
  return s.empty() ? s : " " + s;
}

}  // namespace

std::string fmt_expr(const ast::Expr& e) { return expr_at(e, kTernary); }

std::vector<std::string> fmt_modules(const ast::ModuleSeq& seq) {
  std::vector<std::string> out;
  out.reserve(seq.size());
  for (const ast::ModuleCall& m : seq) {
    out.push_back(m.has_parens || !m.args.empty() ? m.name + "(" + args_text(m.args) + ")"
                                                  : m.name);
  }
  return out;
}

std::string fmt_pattern(const ast::ModulePattern& p) {
  if (!p.has_parens && p.params.empty()) return p.name;
  std::string s = p.name + "(";
  for (std::size_t i = 0; i < p.params.size(); ++i) {
    if (i > 0) s += ", ";
    s += p.params[i].name;
  }
  return s + ")";
}

std::string fmt_pattern_seq(const std::vector<ast::ModulePattern>& seq) {
  std::string out;
  for (const ast::ModulePattern& p : seq) append_module(out, fmt_pattern(p));
  return out;
}

std::string fmt_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string fmt_import(const ast::Import& d) {
  return "import " + (d.is_file ? fmt_string(d.path) : d.path) + ";";
}

std::string fmt_const(const ast::ConstDecl& d) {
  std::string s = d.is_param ? "param " : "const ";
  for (std::size_t i = 0; i < d.bindings.size(); ++i) {
    if (i > 0) s += ", ";
    s += d.bindings[i].name.name + " = " + fmt_expr(d.bindings[i].value);
  }
  return s + ";";
}

std::string fmt_module_decl(const ast::ModuleDecl& d) {
  std::string s = "module ";
  for (std::size_t i = 0; i < d.modules.size(); ++i) {
    if (i > 0) s += ", ";
    s += fmt_pattern(d.modules[i]);
  }
  return s + ";";
}

std::string fmt_setting(const ast::Setting& s) { return s.key.name + values_text(s.values) + ";"; }

std::string fmt_symbol_set(const ast::SymbolSet& s) {
  std::string out = s.consider ? "consider" : "ignore";
  for (const ast::Identifier& id : s.symbols) out += " " + id.name;
  return out + ";";
}

std::string fmt_select(const ast::Select& s) {
  std::string out = "select " + s.mode.name;
  if (!s.keys.empty()) out.append("(").append(args_text(s.keys)).append(")");
  return out + ";";
}

std::string fmt_production_head(const ast::Production& p) {
  std::string s;
  if (p.kind == ast::ProductionKind::Interpret) s = "interpret ";
  if (p.kind == ast::ProductionKind::Decompose) s = "decompose ";
  if (!p.left_context.empty()) s += fmt_pattern_seq(p.left_context) + " < ";
  s += fmt_pattern(p.predecessor);
  if (!p.right_context.empty()) s += " > " + fmt_pattern_seq(p.right_context);
  if (p.guard) s += " : " + fmt_expr(*p.guard);
  if (!p.key.empty()) s.append(" @ (").append(args_text(p.key)).append(")");
  return s + " ->";
}

std::string fmt_probability(const ast::Alternative& a) {
  if (!a.probability) return "";
  // The probability is always parenthesized by the syntax; no double parentheses.
  return std::string("(").append(bare_expr(*a.probability)).append(")");
}

std::string fmt_rim(const ast::RimDecl& r) {
  return "rim " + r.name.name + "(" + named_args_text(r.args) + ");";
}

std::string fmt_piece(const ast::PieceDecl& p) {
  const ast::Constructor& c = p.ctor;
  std::string inner = c.path ? fmt_string(*c.path) : named_args_text(c.args);
  return "piece " + p.name.name + " = " + c.kind.name + "(" + inner + ");";
}

std::string fmt_attach(const ast::AttachRule& a) {
  std::string s = a.piece.name + "." + a.rim.name + " ->";
  for (std::size_t i = 0; i < a.targets.size(); ++i) {
    s += i > 0 ? " | " : " ";
    s += a.targets[i].piece.name;
    if (a.targets[i].weight) s.append(" ").append(expr_at(*a.targets[i].weight, kUnary));
  }
  return s + ";";
}

std::string fmt_piece_setting(const ast::PieceSetting& s) {
  return s.key.name + values_text(s.values) + ";";
}

std::string fmt_voxel_setting(const ast::VoxelSetting& s) {
  if (s.path) return s.key.name + " " + fmt_string(*s.path) + ";";
  return s.key.name + values_text(s.values) + ";";
}

std::string fmt_voxel_rule(const ast::VoxelRule& r) {
  // Children are separated by spaces only, so each is a primary: `[0 (-1) ...]`, never `0 -1`.
  // A name before a child in parentheses would read as a call, `u (!u)` as `u(!u)`: such a
  // name is parenthesised too, `(u) (!u)`. From the last child back, so that a name before a
  // name that this parenthesises is parenthesised as well: `s h (!u)` -> `(s) (h) (!u)`, not
  // `s (h) (!u)`, which reads as `s(h) (!u)`.
  std::vector<std::string> children;
  for (const ast::Expr& c : r.children) children.push_back(expr_at(c, kPrimary));
  for (std::size_t i = children.size(); i-- > 0;) {
    const bool bare_name = std::holds_alternative<ast::NameRef>(r.children[i].node) &&
                           children[i].front() != '(';  // not already written in parentheses
    if (bare_name && i + 1 < children.size() && children[i + 1].front() == '(') {
      children[i] = "(" + children[i] + ")";
    }
  }
  std::string s = expr_at(r.parent, kTernary) + " -> [";
  for (std::size_t i = 0; i < children.size(); ++i) s += (i > 0 ? " " : "") + children[i];
  s += "]";
  if (r.weight) {
    std::string w = expr_at(*r.weight, kPrimary);
    s += (is_name_char(w.front()) && !(w.front() >= '0' && w.front() <= '9')) ? " x " : " x";
    s += w;
  }
  return s + ";";
}

}  // namespace ramus::detail
