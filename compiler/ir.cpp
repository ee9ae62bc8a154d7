#include "compiler/ir.h"

#include <stdexcept>

#include "core/number_text.h"
#include "grammar/builtins.h"

namespace ramus::ir {

namespace {

std::string num(double v) { return shortest_text(v); }

const char* op_name(Op op) {
  switch (op) {
    case Op::Const:
      return "const";
    case Op::Load:
      return "load";
    case Op::Neg:
      return "neg";
    case Op::Not:
      return "not";
    case Op::Add:
      return "add";
    case Op::Sub:
      return "sub";
    case Op::Mul:
      return "mul";
    case Op::Div:
      return "div";
    case Op::Mod:
      return "mod";
    case Op::Pow:
      return "pow";
    case Op::Eq:
      return "eq";
    case Op::Ne:
      return "ne";
    case Op::Lt:
      return "lt";
    case Op::Le:
      return "le";
    case Op::Gt:
      return "gt";
    case Op::Ge:
      return "ge";
    case Op::And:
      return "and";
    case Op::Or:
      return "or";
    case Op::Jump:
      return "jump";
    case Op::JumpIfFalse:
      return "jump_if_false";
    case Op::Call:
      return "call";
  }
  return "?";
}

std::string pattern_text(const Grammar& g, const Pattern& p) {
  std::string s = g.symbols[p.symbol].name;
  if (!p.any_params) {
    s += "(";
    for (int i = 0; i < p.nparams; ++i) {
      if (i) s += ",";
      s += "$" + std::to_string(p.first_slot + i);
    }
    s += ")";
  }
  return s;
}

void dump_modules(const Grammar& g, std::uint32_t b, std::uint32_t e,
                  const std::vector<SuccModule>& mods, std::string& out) {
  for (std::uint32_t i = b; i < e; ++i) {
    const SuccModule& m = mods[i];
    out += " " + g.symbols[m.symbol].name;
    if (m.nargs) {
      out += "(";
      for (int k = 0; k < m.nargs; ++k) {
        if (k) out += ", ";
        out += "{" + dump_code(g, g.args[m.arg_begin + k]) + "}";
      }
      out += ")";
    }
  }
}

void dump_production(const Grammar& g, std::uint32_t pi, std::string& out) {
  const Production& p = g.productions[pi];
  static const char* kinds[] = {"rewrite", "interpret", "decompose"};
  out += "production " + std::to_string(pi) + " " + kinds[int(p.kind)] + " (" +
         g.locations[p.where] + ") slots=" + std::to_string(p.nslots) + "\n ";
  for (const auto& l : p.left) out += " " + pattern_text(g, l);
  if (!p.left.empty()) out += " <";
  out += " " + pattern_text(g, p.predecessor);
  if (!p.right.empty()) out += " >";
  for (const auto& r : p.right) out += " " + pattern_text(g, r);
  if (p.guard != kNoCode) out += " : {" + dump_code(g, p.guard) + "}";
  if (!p.key.empty()) {  // rule-space key and the `select nearest` query in this production's slots
    out += " @ (";
    for (std::size_t k = 0; k < p.key.size(); ++k) {
      out += (k ? ", " : "") + shortest_text(p.key[k]) + " ~ {" + dump_code(g, p.query[k]) + "}";
    }
    out += ")";
  }
  out += "\n";
  for (std::uint32_t a = p.alt_begin; a < p.alt_end; ++a) {
    const Alternative& alt = g.alternatives[a];
    out += "  ->";
    if (alt.probability != kNoCode) out += " ({" + dump_code(g, alt.probability) + "})";
    dump_modules(g, alt.succ_begin, alt.succ_end, g.successors, out);
    out += "\n";
  }
}

}  // namespace

TurtleOp polygon_op(const std::string& name) {
  if (name == "{") return TurtleOp::PolygonBegin;
  if (name == ".") return TurtleOp::Vertex;
  if (name == "}") return TurtleOp::PolygonEnd;
  if (name == "G") return TurtleOp::MoveNoVertex;
  return TurtleOp::None;
}

SymbolId Grammar::intern(const std::string& n) {
  int found = find_symbol(n);
  if (found >= 0) return SymbolId(found);
  if (symbols.size() >= 0xffff) throw std::length_error("more than 65535 module symbols");
  symbols.push_back(Symbol{n, -1, polygon_op(n)});
  ignored.push_back(0);
  return SymbolId(symbols.size() - 1);
}

int Grammar::find_symbol(const std::string& n) const {
  for (std::size_t i = 0; i < symbols.size(); ++i) {
    if (symbols[i].name == n) return int(i);
  }
  return -1;
}

const Table& Grammar::table(Kind k) const {
  switch (k) {
    case Kind::Interpret:
      return interpret;
    case Kind::Decompose:
      return decompose;
    default:
      return rewrite;
  }
}

void Grammar::build_tables() {
  for (Kind k : {Kind::Rewrite, Kind::Interpret, Kind::Decompose}) {
    Table& t = const_cast<Table&>(table(k));
    t = Table{};
    t.first.assign(symbols.size() + 1, 0);
    for (const Production& p : productions) {
      if (p.kind == k) ++t.first[p.predecessor.symbol + 1];
    }
    for (std::size_t s = 0; s < symbols.size(); ++s) t.first[s + 1] += t.first[s];
    t.index.resize(t.first.back());
    std::vector<std::uint32_t> fill(t.first.begin(), t.first.end() - 1);
    for (std::uint32_t i = 0; i < productions.size(); ++i) {
      const Production& p = productions[i];
      if (p.kind != k) continue;
      t.index[fill[p.predecessor.symbol]++] = i;
      t.has_context = t.has_context || p.has_context();
      t.has_left = t.has_left || !p.left.empty();
      t.has_right = t.has_right || !p.right.empty();
    }
  }
}

Grammar make_grammar(std::string name) {
  Grammar g;
  g.name = std::move(name);
  for (int i = 0; i < kTurtleSymbolCount; ++i) {
    g.symbols.push_back(Symbol{kTurtleNames[i], -1, TurtleOp(i)});
    g.ignored.push_back(0);
  }
  g.build_tables();
  return g;
}

std::string dump_code(const Grammar& g, CodeId c) {
  const Code& code = g.codes[c];
  std::string out;
  for (std::uint32_t i = code.begin; i < code.end; ++i) {
    const Instr& in = g.code[i];
    if (i != code.begin) out += "; ";
    out += op_name(in.op);
    switch (in.op) {
      case Op::Const:
        out += " " + num(g.consts[in.a]);
        break;
      case Op::Load:
        out += " $" + std::to_string(in.a);
        break;
      case Op::Jump:
      case Op::JumpIfFalse:
        out += " @" + std::to_string(in.a - code.begin);
        break;
      case Op::Call:
        out += " " + std::string(kBuiltins[in.a].name);
        break;
      default:
        break;
    }
  }
  return out;
}

std::string dump(const Grammar& g) {
  std::string out = "lsystem " + g.name + "\n";
  const Settings& s = g.settings;
  out += "settings derive=" + std::to_string(s.derive) + " seed=" + std::to_string(s.seed) +
         " angle=" + num(s.angle) + " step=" + num(s.step) + " width=" + num(s.width) +
         " width_decay=" + num(s.width_decay) + " tropism=" + num(s.tropism[0]) + "," +
         num(s.tropism[1]) + "," + num(s.tropism[2]) + " elasticity=" + num(s.elasticity) +
         " max_depth=" + std::to_string(s.max_depth) + "\n";
  if (g.selection == Selection::Nearest) out += "selection nearest\n";
  for (const Constant& c : g.constants) {
    out += std::string(c.is_param ? "param " : "const ") + c.name + " = " + num(c.value) + "\n";
  }
  for (std::size_t i = kTurtleSymbolCount; i < g.symbols.size(); ++i) {
    out += "symbol " + std::to_string(i) + " " + g.symbols[i].name +
           " arity=" + std::to_string(g.symbols[i].arity) + (g.ignored[i] ? " ignored" : "") + "\n";
  }
  for (int i = 0; i < kTurtleSymbolCount; ++i) {
    if (g.ignored[i]) out += "ignored " + g.symbols[i].name + "\n";
  }
  out += "axiom";
  dump_modules(g, 0, std::uint32_t(g.axiom.size()), g.axiom, out);
  out += "\n";
  for (std::uint32_t i = 0; i < g.productions.size(); ++i) dump_production(g, i, out);
  return out;
}

}  // namespace ramus::ir
