#include "formats/rmb/rmb_decompile.h"

#include <cctype>
#include <cmath>
#include <map>
#include <set>

#include "compiler/pipeline.h"
#include "core/number_text.h"
#include "formats/rmb/rmb_pieces_ast.h"
#include "formats/rmb/rmb_voxels.h"
#include "grammar/builtins.h"
#include "grammar/check.h"
#include "grammar/format.h"
#include "grammar/loader.h"
#include "grammar/modules.h"

namespace ramus {

namespace {

ast::Expr make(decltype(ast::Expr::node) node) {
  ast::Expr e;
  e.node = std::move(node);
  return e;
}

ast::Expr number(double v) { return decompiled_number(v); }

ast::Identifier ident(std::string name) { return ast::Identifier{std::move(name), {}}; }

class Decompiler {
 public:
  explicit Decompiler(const ir::Grammar& g) : g_(g) {
    // Constants that can stand for a pool value: unique value, not an integer.
    std::map<double, int> count;
    for (const ir::Constant& c : g_.constants) ++count[c.value];
    for (std::size_t i = 0; i < g_.constants.size(); ++i) {
      const ir::Constant& c = g_.constants[i];
      if (count[c.value] == 1 && std::isfinite(c.value) && c.value != std::floor(c.value) &&
          is_identifier(c.name) && !find_builtin(c.name) && c.name != "pi" && c.name != "e") {
        by_value_[c.value] = i;
      }
    }
  }

  ast::File run() {
    ast::LSystem ls;
    // The decoder takes any bytes as the block's name; only an identifier can be written back.
    if (!is_identifier(g_.name)) {
      throw DecompileError("lsystem block name \"" + g_.name + "\" is not an identifier");
    }
    ls.name = ident(g_.name);
    settings(ls);
    symbol_set(ls);
    if (g_.selection == ir::Selection::Nearest) ls.items.push_back(select());
    slot_names_.clear();
    ls.items.push_back(ast::Axiom{modules(g_.axiom, 0, std::uint32_t(g_.axiom.size())), {}});
    for (const ir::Production& p : g_.productions) ls.items.push_back(production(p));

    ast::File f;
    for (bool is_param : {true, false}) {
      ast::ConstDecl d;
      d.is_param = is_param;
      for (std::size_t i : used_constants_) {
        const ir::Constant& c = g_.constants[i];
        if (c.is_param == is_param)
          d.bindings.push_back(ast::Binding{ident(c.name), number(c.value)});
      }
      if (!d.bindings.empty()) f.decls.push_back(std::move(d));
    }
    // Names of several characters stand for one module per letter unless declared.
    ast::ModuleDecl md;
    for (std::size_t s = ir::kTurtleSymbolCount; s < g_.symbols.size(); ++s) {
      const std::string& name = g_.symbols[s].name;
      if (ir::polygon_op(name) != ir::TurtleOp::None) continue;  // `{` `.` `}` `G`: turtle symbols
      if (!is_identifier(name))
        throw DecompileError("module name \"" + name + "\" is not an identifier");
      if (name.size() == 1) continue;
      // A declaration fixes the arity: `module Apex(p0, p1)`, or `module Apex` for none.
      ast::ModulePattern decl{name, {}, g_.symbols[s].arity > 0, {}};
      for (int k = 0; k < g_.symbols[s].arity; ++k)
        decl.params.push_back(ident("p" + std::to_string(k)));
      md.modules.push_back(std::move(decl));
    }
    if (!md.modules.empty()) f.decls.push_back(std::move(md));
    f.decls.push_back(std::move(ls));
    return f;
  }

 private:
  // ---- block items ------------------------------------------------------------------------
  void setting(ast::LSystem& ls, const char* key, std::vector<double> values) {
    ast::Setting s;
    s.key = ident(key);
    for (double v : values) s.values.push_back(number(v));
    ls.items.push_back(std::move(s));
  }

  // Only what differs from the defaults (ir::Settings), in the order docs/language.md lists.
  void settings(ast::LSystem& ls) {
    const ir::Settings d;
    const ir::Settings& s = g_.settings;
    if (s.derive != d.derive) setting(ls, "derive", {double(s.derive)});
    if (s.seed != d.seed) {
      if (s.seed > (std::uint64_t(1) << 53)) {
        throw DecompileError("seed " + std::to_string(s.seed) +
                             " is beyond 2^53, which .ramus "
                             "numbers cannot hold exactly");
      }
      setting(ls, "seed", {double(s.seed)});
    }
    auto differs = [](double a, double b) { return std::signbit(a) != std::signbit(b) || a != b; };
    if (differs(s.angle, d.angle)) setting(ls, "angle", {s.angle});
    if (differs(s.step, d.step)) setting(ls, "step", {s.step});
    if (differs(s.width, d.width)) setting(ls, "width", {s.width});
    if (differs(s.width_decay, d.width_decay)) setting(ls, "width_decay", {s.width_decay});
    if (differs(s.tropism[0], d.tropism[0]) || differs(s.tropism[1], d.tropism[1]) ||
        differs(s.tropism[2], d.tropism[2])) {
      setting(ls, "tropism", {s.tropism[0], s.tropism[1], s.tropism[2]});
    }
    if (differs(s.elasticity, d.elasticity)) setting(ls, "elasticity", {s.elasticity});
    if (s.max_depth != d.max_depth) setting(ls, "max_depth", {double(s.max_depth)});
  }

  void symbol_set(ast::LSystem& ls) {
    ast::SymbolSet set;
    for (std::size_t s = 0; s < g_.ignored.size() && s < g_.symbols.size(); ++s) {
      if (g_.ignored[s] && s != ir::kPush && s != ir::kPop) {
        set.symbols.push_back(ident(g_.symbols[s].name));
      }
    }
    if (!set.symbols.empty()) ls.items.push_back(std::move(set));
  }

  // `select nearest(e1, ..., en)`: the query expressions as compiled in the first keyed
  // production, written with its formal names (every keyed production compiles the same
  // expressions in its own slots, so their names agree as they did in the source).
  ast::Select select() {
    ast::Select out{ident("nearest"), {}, {}};
    for (const ir::Production& p : g_.productions) {
      if (p.query.empty()) continue;
      name_slots(p);
      for (ir::CodeId c : p.query) out.keys.push_back(code(c));
      slot_names_.clear();
      break;
    }
    return out;
  }

  ast::ModuleSeq modules(const std::vector<ir::SuccModule>& mods, std::uint32_t b,
                         std::uint32_t e) {
    ast::ModuleSeq out;
    for (std::uint32_t i = b; i < e; ++i) {
      const ir::SuccModule& m = mods[i];
      ast::ModuleCall call;
      call.name = g_.symbols.at(m.symbol).name;
      for (std::uint32_t k = 0; k < m.nargs; ++k)
        call.args.push_back(code(g_.args.at(m.arg_begin + k)));
      call.has_parens = m.nargs > 0;
      out.push_back(std::move(call));
    }
    return out;
  }

  ast::ModulePattern pattern(const ir::Pattern& p) {
    ast::ModulePattern out;
    out.name = g_.symbols.at(p.symbol).name;
    out.has_parens = !p.any_params;
    if (!p.any_params) {
      for (std::uint32_t k = 0; k < p.nparams; ++k)
        out.params.push_back(ident(slot_names_.at(p.first_slot + k)));
    }
    return out;
  }

  // The patterns of `p` in text order: left context, predecessor, right context.
  static std::vector<const ir::Pattern*> text_order(const ir::Production& p) {
    std::vector<const ir::Pattern*> out;
    for (const ir::Pattern& q : p.left) out.push_back(&q);
    out.push_back(&p.predecessor);
    for (const ir::Pattern& q : p.right) out.push_back(&q);
    return out;
  }

  // The formal names as written in p.text: the identifiers of each parenthesized group before
  // the guard or the arrow, one group per pattern with parameters. Empty when the text does
  // not fit the patterns (a stripped or hand-made grammar).
  static std::vector<std::vector<std::string>> written_formals(const ir::Production& p) {
    std::vector<std::vector<std::string>> groups;
    const std::string& t = p.text;
    bool in_group = false;
    for (std::size_t i = 0; i < t.size(); ++i) {
      const char c = t[i];
      if (!in_group && (c == ':' || (c == '-' && i + 1 < t.size() && t[i + 1] == '>'))) break;
      if (c == '(') {
        if (in_group) return {};
        in_group = true;
        groups.emplace_back();
      } else if (c == ')') {
        if (!in_group) return {};
        in_group = false;
      } else if (in_group && (std::isalpha(static_cast<unsigned char>(c)) || c == '_')) {
        std::size_t j = i;
        while (j < t.size() && (std::isalnum(static_cast<unsigned char>(t[j])) || t[j] == '_')) ++j;
        groups.back().push_back(t.substr(i, j - i));
        i = j - 1;
      }
    }
    return groups;
  }

  void name_slots(const ir::Production& p) {
    slot_names_.assign(ir::kMaxSlots, "");
    const auto patterns = text_order(p);
    const auto groups = written_formals(p);
    std::vector<const ir::Pattern*> with_params;
    for (const ir::Pattern* q : patterns) {
      if (!q->any_params) with_params.push_back(q);
    }
    bool fits = groups.size() == with_params.size();
    std::set<std::string> seen;
    for (std::size_t i = 0; fits && i < groups.size(); ++i) {
      fits = groups[i].size() == with_params[i]->nparams;
      for (std::size_t k = 0; fits && k < groups[i].size(); ++k) {
        const std::string& n = groups[i][k];
        fits = seen.insert(n).second && !find_builtin(n) && n != "true" && n != "false";
      }
    }
    for (std::size_t i = 0; i < with_params.size(); ++i) {
      for (std::uint32_t k = 0; k < with_params[i]->nparams; ++k) {
        const std::uint32_t slot = with_params[i]->first_slot + k;
        slot_names_.at(slot) = fits ? groups[i][k] : "p" + std::to_string(slot);
      }
    }
  }

  ast::Production production(const ir::Production& p) {
    name_slots(p);
    ast::Production out;
    out.kind = p.kind == ir::Kind::Rewrite     ? ast::ProductionKind::Rewrite
               : p.kind == ir::Kind::Interpret ? ast::ProductionKind::Interpret
                                               : ast::ProductionKind::Decompose;
    for (const ir::Pattern& q : p.left) out.left_context.push_back(pattern(q));
    out.predecessor = pattern(p.predecessor);
    for (const ir::Pattern& q : p.right) out.right_context.push_back(pattern(q));
    if (p.guard != ir::kNoCode) out.guard = guard(p.guard);
    for (double k : p.key) out.key.push_back(number(k));  // its point in rule space
    for (std::uint32_t a = p.alt_begin; a < p.alt_end; ++a) {
      const ir::Alternative& alt = g_.alternatives.at(a);
      ast::Alternative o;
      if (alt.probability != ir::kNoCode) o.probability = code(alt.probability);
      o.successor = modules(g_.successors, alt.succ_begin, alt.succ_end);
      out.alternatives.push_back(std::move(o));
    }
    slot_names_.clear();
    return out;
  }

  // ---- expressions --------------------------------------------------------------------------
  ast::Expr code(ir::CodeId c) {
    const ir::Code& k = g_.codes.at(c);
    return range(k.begin, k.end);
  }

  // A guard the compiler folded to one constant (`trunk_width > 0` with a param, which lowering
  // makes a constant): the derivation takes it when it is not 0, so it reads `true` or `false`;
  // printed as a number it would not check (a guard is a boolean).
  ast::Expr guard(ir::CodeId c) {
    const ir::Code& k = g_.codes.at(c);
    if (k.end == k.begin + 1 && g_.code[k.begin].op == ir::Op::Const) {
      return make(ast::BoolLit{!(g_.consts.at(g_.code[k.begin].a) == 0)});
    }
    return code(c);
  }

  ast::Expr constant(double v) {
    auto it = by_value_.find(v);
    if (it != by_value_.end()) {
      const std::string& name = g_.constants[it->second].name;
      bool shadowed = false;
      for (const std::string& s : slot_names_) shadowed = shadowed || s == name;
      if (!shadowed) {
        used_constants_.insert(it->second);
        return make(ast::NameRef{name});
      }
    }
    return number(v);
  }

  bool is_const(std::uint32_t i, double v) const {
    return g_.code[i].op == ir::Op::Const && g_.consts.at(g_.code[i].a) == v;
  }

  static ast::Expr binary(ast::BinaryOp op, ast::Expr l, ast::Expr r) {
    return make(
        ast::Binary{op, ast::Box<ast::Expr>(std::move(l)), ast::Box<ast::Expr>(std::move(r))});
  }

  [[noreturn]] static void unexpected(std::uint32_t at, const char* what) {
    throw DecompileError("instruction " + std::to_string(at) + ": " + what);
  }

  // The instructions [b, e) as one expression tree.
  ast::Expr range(std::uint32_t b, std::uint32_t e) {
    if (b >= e || e > g_.code.size()) unexpected(b, "an empty or out-of-range expression");
    std::vector<ast::Expr> st;
    auto pop = [&](std::uint32_t at) {
      if (st.empty()) unexpected(at, "the stack is empty");
      ast::Expr x = std::move(st.back());
      st.pop_back();
      return x;
    };
    for (std::uint32_t i = b; i < e;) {
      const ir::Instr in = g_.code[i];
      switch (in.op) {
        case ir::Op::Const:
          st.push_back(constant(g_.consts.at(in.a)));
          break;
        case ir::Op::Load:
          if (in.a >= slot_names_.size() || slot_names_[in.a].empty()) {
            unexpected(i, "a slot no pattern binds");
          }
          st.push_back(make(ast::NameRef{slot_names_[in.a]}));
          break;
        case ir::Op::Neg:
        case ir::Op::Not: {
          ast::Expr x = pop(i);
          const auto op = in.op == ir::Op::Neg ? ast::UnaryOp::Neg : ast::UnaryOp::Not;
          st.push_back(make(ast::Unary{op, ast::Box<ast::Expr>(std::move(x))}));
          break;
        }
        case ir::Op::Jump:
          unexpected(i, "a jump outside a conditional");
        case ir::Op::JumpIfFalse: {
          st.push_back(conditional(i, e, pop(i)));
          i = jump_end_;
          continue;
        }
        case ir::Op::Call: {
          if (in.a >= std::size(kBuiltins)) unexpected(i, "an unknown builtin");
          const BuiltinInfo& info = kBuiltins[in.a];
          if (st.size() < info.arity) unexpected(i, "the stack is too shallow for the call");
          ast::Call call;
          call.callee = ident(std::string(info.name));
          for (std::size_t k = st.size() - info.arity; k < st.size(); ++k)
            call.args.push_back(std::move(st[k]));
          st.resize(st.size() - info.arity);
          st.push_back(make(std::move(call)));
          break;
        }
        default: {  // binary operators, in ir::Op order from Add
          static constexpr ast::BinaryOp kOps[] = {
              ast::BinaryOp::Add, ast::BinaryOp::Sub, ast::BinaryOp::Mul, ast::BinaryOp::Div,
              ast::BinaryOp::Mod, ast::BinaryOp::Pow, ast::BinaryOp::Eq,  ast::BinaryOp::Ne,
              ast::BinaryOp::Lt,  ast::BinaryOp::Le,  ast::BinaryOp::Gt,  ast::BinaryOp::Ge,
              ast::BinaryOp::And, ast::BinaryOp::Or};
          ast::Expr r = pop(i);
          ast::Expr l = pop(i);
          st.push_back(binary(kOps[int(in.op) - int(ir::Op::Add)], std::move(l), std::move(r)));
        }
      }
      ++i;
    }
    if (st.size() != 1) unexpected(b, "an expression that leaves other than one value");
    return std::move(st.back());
  }

  // `cond; jump_if_false T; then; jump J; T: else; J:` (compiler/expr_compile.cpp), read back as
  // `&&` (then = rhs != 0, else = 0), `||` (then = 1, else = rhs != 0) or `?:`. Sets jump_end_.
  ast::Expr conditional(std::uint32_t at, std::uint32_t e, ast::Expr cond) {
    const std::uint32_t t = g_.code[at].a;
    if (t < at + 3 || t > e || g_.code[t - 1].op != ir::Op::Jump) {
      unexpected(at, "a jump that is not an if-then-else");
    }
    const std::uint32_t j = g_.code[t - 1].a;
    if (j <= t || j > e) unexpected(t - 1, "a jump that is not an if-then-else");
    jump_end_ = j;
    const bool then_ne0 = t >= at + 5 && g_.code[t - 2].op == ir::Op::Ne && is_const(t - 3, 0);
    const bool else_ne0 = j >= t + 3 && g_.code[j - 1].op == ir::Op::Ne && is_const(j - 2, 0);
    if (then_ne0 && j == t + 1 && is_const(t, 0)) {
      ast::Expr rhs = range(at + 1, t - 3);
      jump_end_ = j;
      return binary(ast::BinaryOp::And, std::move(cond), std::move(rhs));
    }
    if (else_ne0 && t == at + 3 && is_const(at + 1, 1)) {
      ast::Expr rhs = range(t, j - 2);
      jump_end_ = j;
      return binary(ast::BinaryOp::Or, std::move(cond), std::move(rhs));
    }
    ast::Expr then_e = range(at + 1, t - 1);
    ast::Expr else_e = range(t, j);
    jump_end_ = j;
    return make(ast::Conditional{ast::Box<ast::Expr>(std::move(cond)),
                                 ast::Box<ast::Expr>(std::move(then_e)),
                                 ast::Box<ast::Expr>(std::move(else_e))});
  }

  const ir::Grammar& g_;
  std::map<double, std::size_t> by_value_;  // pool value -> the constant it may be written as
  std::set<std::size_t> used_constants_;
  std::vector<std::string> slot_names_;  // of the production being decompiled
  std::uint32_t jump_end_ = 0;
};

}  // namespace

// The decoder checks the structure of a file, not every rule of the language (a built-in module
// with 17 parameters decodes and runs); text that `ramus check` would refuse is not written.
namespace {

std::string checked(std::string text) {
  SourceManager sm;
  DiagnosticSink diags;
  Program program = load_program_text("decompiled.ramus", text, sm, diags);
  if (!diags.has_errors() && !program.files.empty()) check_program(program, sm, diags);
  for (const Diagnostic& d : diags.all()) {
    if (d.severity == Severity::Error) {
      throw DecompileError("the grammar breaks a rule of the language: " + d.message);
    }
  }
  // Lowering checks the values of the settings (max_depth 0 decodes and runs, clamped).
  const bool has_lsystem =
      std::any_of(program.files[0].decls.begin(), program.files[0].decls.end(),
                  [](const ast::Decl& d) { return std::holds_alternative<ast::LSystem>(d); });
  if (has_lsystem) {
    try {
      lower_checked(program, GrowOptions{}, sm, diags);
    } catch (const std::exception& e) {
      throw DecompileError(std::string("the grammar breaks a rule of the language: ") + e.what());
    }
  }
  return text;
}

}  // namespace

ast::File decompile_to_ast(const ir::Grammar& g) { return Decompiler(g).run(); }

std::string decompile(const ir::Grammar& g) { return checked(format_file(decompile_to_ast(g))); }

std::string decompile(const RmbContents& contents) {
  ast::File file;
  if (rmb_has_lsystem(contents.grammar)) file = decompile_to_ast(contents.grammar);
  for (const RmbPieceSet& s : contents.pieces.sets) {
    // Names the language cannot spell would print as other tokens.
    auto name_ok = [](const std::string& n, const char* what) {
      if (!is_identifier(n)) {
        throw DecompileError(std::string(what) + " \"" + n + "\" is not an identifier");
      }
    };
    name_ok(s.name, "pieces block name");
    for (const RmbPiece& p : s.pieces) {
      name_ok(p.name, "piece name");
      for (unsigned char c : p.path) {  // a .ramus string has no escapes
        if (c < 0x20 || c == '"' || c == 0x7f) {
          throw DecompileError("the mesh path of piece " + p.name + " has no .ramus spelling");
        }
      }
    }
    for (const RmbAttachRule& r : s.rules) name_ok(r.rim, "rim name");
    file.decls.emplace_back(pieces_to_ast(s, contents.pieces));
  }
  for (const RmbVoxelTable& t : contents.voxels) file.decls.emplace_back(voxels_to_ast(t));
  return checked(format_file(file));
}

std::string decompile_left_out(const RmbContents& contents) {
  if (contents.placed.empty()) return "";
  std::size_t pieces = 0;
  for (const RmbPlacedTree& t : contents.placed.trees) pieces += t.pieces.size();
  return "the placed pieces (section 12: " + std::to_string(contents.placed.trees.size()) +
         " tree(s), " + std::to_string(pieces) + " pieces of set '" + contents.placed.set +
         "') are a built tree, not grammar text; `ramus build --target binary --placed-pieces` "
         "stores them again";
}

}  // namespace ramus
