// ir::Grammar: what lowering makes of an `lsystem` block and what derivation, the turtle and the
// binary format (.rmb) read. Plain data only -- vectors of records addressed by integer ids, no
// pointers -- so that the binary format can serialize exactly this and a Grammar can be copied.
//
// Layout (docs/engine.md):
//   symbols      interned module names; ids 0..15 are the turtle symbols in TurtleOp order
//   code/consts  every expression as flat bytecode for the stack VM of compiler/expr_vm.h
//   productions  one record per production, in file order, with patterns and alternatives
//   tables       per kind (rewrite, interpret, decompose): the productions of each predecessor
//                symbol in file order, as offsets into one index array
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace ramus::ir {

using SymbolId = std::uint16_t;
using CodeId = std::uint32_t;
inline constexpr CodeId kNoCode = std::numeric_limits<CodeId>::max();
inline constexpr std::uint32_t kMaxSlots = 64;  // formal parameters bound by one production

// The turtle symbols, with their fixed symbol ids (docs/language.md, turtle table).
enum class TurtleOp : std::uint8_t {
  Forward,     // F
  Move,        // f
  Left,        // +
  Right,       // -
  PitchDown,   // &
  PitchUp,     // ^
  RollLeft,    // '\'
  RollRight,   // /
  TurnAround,  // |
  Level,       // $
  Push,        // [
  Pop,         // ]
  Width,       // !
  Colour,      // '
  Organ,       // ~
  Cut,         // %
  // The polygon symbols of ABOP 5.2 (developmental surfaces). They have no fixed symbol id: a
  // grammar interns them by name like any module (polygon_op below), so the symbol ids and the
  // .rmb layout of grammars without polygons are what they were.
  PolygonBegin,  // {
  Vertex,        // .
  PolygonEnd,    // }
  MoveNoVertex,  // G
  None,          // any other module
};
inline constexpr int kTurtleSymbolCount = 16;
inline constexpr const char* kTurtleNames[kTurtleSymbolCount] = {
    "F", "f", "+", "-", "&", "^", "\\", "/", "|", "$", "[", "]", "!", "'", "~", "%"};
inline constexpr SymbolId kPush = SymbolId(TurtleOp::Push);
inline constexpr SymbolId kPop = SymbolId(TurtleOp::Pop);
inline constexpr SymbolId kCut = SymbolId(TurtleOp::Cut);

// The turtle meaning of a symbol without a fixed id: `{`, `.`, `}` and `G` are the polygon
// symbols, anything else is TurtleOp::None.
TurtleOp polygon_op(const std::string& name);

struct Symbol {
  std::string name;
  std::int16_t arity = -1;  // declared or consistently used parameter count; -1 when it varies
  TurtleOp turtle = TurtleOp::None;
};

// ---- expressions ------------------------------------------------------------------------------

enum class Op : std::uint8_t {
  Const,  // push consts[a]
  Load,   // push slot a
  Neg,
  Not,
  Add,
  Sub,
  Mul,
  Div,
  Mod,
  Pow,
  Eq,
  Ne,
  Lt,
  Le,
  Gt,
  Ge,
  And,
  Or,           // on truth values (both operands evaluated; they have no side effects but draws)
  Jump,         // pc = a
  JumpIfFalse,  // pop; if zero, pc = a
  Call,         // builtin a (ramus::Builtin), its arity popped
};

struct Instr {
  Op op;
  std::uint32_t a = 0;
};

// One compiled expression: instructions [begin, end) of Grammar::code. `shape` lets the hot loop
// skip the VM for the most common forms of L-system arguments: a constant, a bare parameter, and
// a parameter combined with a constant (`s * r`, `s / 1.456`, `x + 1`).
struct Code {
  enum class Shape : std::uint8_t { General, Constant, Param, ParamOpConst };
  std::uint32_t begin = 0, end = 0;
  std::uint16_t max_stack = 0;
  Shape shape = Shape::General;
  bool random = false;      // draws from the module's stream (uniform, normal)
  Op op = Op::Add;          // Shape::ParamOpConst: slot op value
  double value = 0;         // Shape::Constant, ParamOpConst
  std::uint32_t slot = 0;   // Shape::Param, ParamOpConst
  std::uint32_t where = 0;  // index into Grammar::locations ("file:line:col")
};

// ---- productions --------------------------------------------------------------------------------

// A module in a predecessor or context. Without parentheses it matches the symbol with any
// parameters; with them, exactly `nparams` parameters, bound to slots first_slot...
struct Pattern {
  SymbolId symbol = 0;
  bool any_params = true;
  std::uint16_t nparams = 0;
  std::uint16_t first_slot = 0;
};

// A module of a successor: symbol and argument codes args[arg_begin, arg_begin + nargs).
struct SuccModule {
  SymbolId symbol = 0;
  std::uint16_t nargs = 0;
  std::uint32_t arg_begin = 0;  // into Grammar::args
};

struct Alternative {
  std::uint32_t production = 0;
  CodeId probability = kNoCode;                // kNoCode: deterministic
  std::uint32_t succ_begin = 0, succ_end = 0;  // into Grammar::successors
  std::uint32_t out_params = 0;                // parameters the successor writes
};

enum class Kind : std::uint8_t { Rewrite, Interpret, Decompose };

struct Production {
  Kind kind = Kind::Rewrite;
  Pattern predecessor;
  std::vector<Pattern> left;   // in text order; matched right to left from the predecessor
  std::vector<Pattern> right;  // in text order; may contain [ and ] (lpfg)
  CodeId guard = kNoCode;
  std::uint32_t alt_begin = 0, alt_end = 0;  // into Grammar::alternatives
  std::uint16_t nslots = 0;
  std::uint32_t where = 0;  // index into Grammar::locations
  std::string text;         // the production as written, for error messages and dumps
  // Rule-space selection (Selection::Nearest): the production's constant key `@ (k1, ..., kn)`
  // and the `select nearest(e1, ..., en)` expressions compiled in this production's slots. Both
  // empty for a production without a key.
  std::vector<double> key;
  std::vector<CodeId> query;
  bool has_context() const { return !left.empty() || !right.empty(); }
};

// The productions of one kind, grouped by predecessor symbol in file order:
// productions index[first[s] .. first[s+1]) have predecessor s.
struct Table {
  std::vector<std::uint32_t> first;  // size symbols + 1
  std::vector<std::uint32_t> index;
  bool has_context = false;
  bool has_left = false, has_right = false;  // some production has a left / right context
  bool empty() const { return index.empty(); }
};

// How a module picks among the matching productions: the first in file order, or the keyed
// production nearest in rule space (`select nearest(...)`, Friedman & Stamos III-G; derive.cpp).
enum class Selection : std::uint8_t { FirstMatch, Nearest };

struct Settings {
  int derive = 0;
  std::uint64_t seed = 0;
  double angle = 90;
  double step = 1;
  double width = 1;
  double width_decay = 0.707;
  double tropism[3] = {0, 0, -1};
  double elasticity = 0;
  int max_depth = 8;
};

struct Constant {
  std::string name;
  double value = 0;
  bool is_param = false;
};

struct Grammar {
  std::string name;  // the lsystem block
  std::vector<Symbol> symbols;
  std::vector<Constant> constants;

  std::vector<Instr> code;
  std::vector<double> consts;
  std::vector<Code> codes;
  std::vector<CodeId> args;  // successor and axiom argument lists
  std::vector<std::string> locations;

  std::vector<Production> productions;
  std::vector<Alternative> alternatives;
  std::vector<SuccModule> successors;
  Table rewrite, interpret, decompose;

  std::vector<SuccModule> axiom;      // arguments are constant codes (no slots)
  std::vector<std::uint8_t> ignored;  // per symbol: 1 if context matching skips it
  Settings settings;
  Selection selection = Selection::FirstMatch;

  // Interns `name` (returns the existing id if present). Turtle symbols are always ids 0..15.
  SymbolId intern(const std::string& name);
  // -1 when not interned.
  int find_symbol(const std::string& name) const;
  const Table& table(Kind k) const;
  // Fills the three tables from `productions` (call after adding all productions).
  void build_tables();
};

// A fresh grammar holding only the turtle symbols.
Grammar make_grammar(std::string name);

// A readable text dump for golden tests: symbols, settings, productions with bytecode.
std::string dump(const Grammar& g);
// One expression's bytecode in readable form, e.g. "load 0; const 1.456; div".
std::string dump_code(const Grammar& g, CodeId c);

}  // namespace ramus::ir
