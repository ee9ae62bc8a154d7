// The ramus AST: close to the syntax of docs/language.md, with a SourceSpan on every node.
//
// Plain C++ (std::variant, vectors, a copyable Box for recursion) so that the stages that read it
// (checks, formatter, lowering, decompiler) never see Spirit X3, which stays inside grammar/'s
// single parser translation unit. Names are kept exactly as written: an undeclared
// multi-letter name such as `FF` is split into single-letter modules only by
// `split_module_name()` (grammar/modules.h), so the formatter can print what the user wrote.
//
// operator== compares syntax only, never spans: "the AST of fmt(x) equals the AST of x".
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "grammar/source.h"

namespace ramus::ast {

// A copyable owning pointer, for recursive nodes.
template <typename T>
class Box {
 public:
  Box() : p_(std::make_unique<T>()) {}
  Box(T v) : p_(std::make_unique<T>(std::move(v))) {}  // NOLINT: implicit by design
  Box(const Box& o) : p_(std::make_unique<T>(*o.p_)) {}
  Box(Box&&) noexcept = default;
  Box& operator=(const Box& o) {
    p_ = std::make_unique<T>(*o.p_);
    return *this;
  }
  Box& operator=(Box&&) noexcept = default;
  T& operator*() { return *p_; }
  const T& operator*() const { return *p_; }
  T* operator->() { return p_.get(); }
  const T* operator->() const { return p_.get(); }
  bool operator==(const Box& o) const { return *p_ == *o.p_; }

 private:
  std::unique_ptr<T> p_;
};

struct Identifier {
  std::string name;
  SourceSpan span;
  bool operator==(const Identifier& o) const { return name == o.name; }
};

// ---- expressions -------------------------------------------------------------------------

struct Expr;

struct NumberLit {
  double value = 0;
  std::string text;  // as written, so the formatter keeps 0.50 as 0.50
  bool operator==(const NumberLit& o) const { return value == o.value; }
};
struct BoolLit {
  bool value = false;
  bool operator==(const BoolLit&) const = default;
};
struct NameRef {  // a constant, param, or formal parameter
  std::string name;
  bool operator==(const NameRef&) const = default;
};
enum class UnaryOp { Neg, Plus, Not };
struct Unary {
  UnaryOp op;
  Box<Expr> operand;
  bool operator==(const Unary&) const = default;
};
// Precedence, loosest first: ?: || && (== !=) (< <= > >=) (+ -) (* / %) unary ^ (right assoc).
enum class BinaryOp { Or, And, Eq, Ne, Lt, Le, Gt, Ge, Add, Sub, Mul, Div, Mod, Pow };
struct Binary {
  BinaryOp op;
  Box<Expr> lhs, rhs;
  bool operator==(const Binary&) const = default;
};
struct Conditional {  // c ? a : b
  Box<Expr> cond, then_expr, else_expr;
  bool operator==(const Conditional&) const = default;
};
struct Call {  // sin(x), uniform(a, b), normal(m, s), ...
  Identifier callee;
  std::vector<Expr> args;
  bool operator==(const Call&) const = default;
};

struct Expr {
  std::variant<NumberLit, BoolLit, NameRef, Unary, Binary, Conditional, Call> node;
  SourceSpan span;
  bool parenthesized = false;  // written inside ( ), kept for the formatter only
  bool operator==(const Expr& o) const { return node == o.node; }
};

// ---- modules -----------------------------------------------------------------------------

// A module in an axiom or successor: `A(l*r1, w)`, `F`, `+(30)`, `[`, `FF`.
// `name` is the symbol as written: an identifier or one turtle character (+ - & ^ \ / | $ [ ] ! ' ~
// %).
struct ModuleCall {
  std::string name;
  std::vector<Expr> args;
  bool has_parens = false;  // `A()` vs `A`
  SourceSpan span;
  bool operator==(const ModuleCall& o) const {
    return name == o.name && args == o.args && has_parens == o.has_parens;
  }
};
using ModuleSeq = std::vector<ModuleCall>;

// A module in a predecessor or context: `A(l, w)`, `F`, `[`, `]`. Parameters are formal names.
struct ModulePattern {
  std::string name;
  std::vector<Identifier> params;
  bool has_parens = false;
  SourceSpan span;
  bool operator==(const ModulePattern& o) const {
    return name == o.name && params == o.params && has_parens == o.has_parens;
  }
};

// ---- declarations at file level -------------------------------------------------------------

struct Import {  // import "path/file.ramus";  or  import trees;  (stdlib/trees.ramus)
  std::string path;
  bool is_file = false;  // quoted path
  SourceSpan span;
  bool operator==(const Import& o) const { return path == o.path && is_file == o.is_file; }
};

struct Binding {
  Identifier name;
  Expr value;
  bool operator==(const Binding&) const = default;
};
struct ConstDecl {  // const a = 1, b = 2;   param seed = 1;
  bool is_param = false;
  std::vector<Binding> bindings;
  SourceSpan span;
  bool operator==(const ConstDecl& o) const {
    return is_param == o.is_param && bindings == o.bindings;
  }
};

struct ModuleDecl {  // module A(l, w), Apex, B(x);
  std::vector<ModulePattern> modules;
  SourceSpan span;
  bool operator==(const ModuleDecl& o) const { return modules == o.modules; }
};

// ---- lsystem blocks ---------------------------------------------------------------------------

// derive N; seed S; angle A; step S; width W; elasticity E; tropism x, y, z; max_depth D;
// (the settings a block may hold are listed in docs/language.md and checked, not parsed, so a
// misspelt setting gets a diagnostic rather than a parse error)
struct Setting {
  Identifier key;
  std::vector<Expr> values;
  SourceSpan span;
  bool operator==(const Setting& o) const { return key == o.key && values == o.values; }
};
struct Axiom {
  ModuleSeq modules;
  SourceSpan span;
  bool operator==(const Axiom& o) const { return modules == o.modules; }
};
struct SymbolSet {  // ignore + - F;   consider A B;
  bool consider = false;
  std::vector<Identifier> symbols;
  SourceSpan span;
  bool operator==(const SymbolSet& o) const {
    return consider == o.consider && symbols == o.symbols;
  }
};
// nearest-rule selection (rule space of Friedman & Stamos III-G): select nearest(e1, e2, ...);
struct Select {
  Identifier mode;         // "nearest" or "first" (the default)
  std::vector<Expr> keys;  // the coordinates in rule space, over the predecessor's parameters
  SourceSpan span;
  bool operator==(const Select& o) const { return mode == o.mode && keys == o.keys; }
};

struct Alternative {  // (p) successor    -- p absent for a deterministic production
  std::optional<Expr> probability;
  ModuleSeq successor;
  SourceSpan span;
  bool operator==(const Alternative& o) const {
    return probability == o.probability && successor == o.successor;
  }
};
enum class ProductionKind { Rewrite, Interpret, Decompose };
// [left <] predecessor [> right] [: guard] [@ (k1, ..., kn)] -> alternatives ;
struct Production {
  ProductionKind kind = ProductionKind::Rewrite;
  std::vector<ModulePattern> left_context;
  ModulePattern predecessor;
  std::vector<ModulePattern> right_context;
  std::optional<Expr> guard;
  // The production's point in rule space (`select nearest`); empty when it has none.
  std::vector<Expr> key;
  std::vector<Alternative> alternatives;  // one, or several each with a probability
  SourceSpan span;
  bool operator==(const Production& o) const {
    return kind == o.kind && left_context == o.left_context && predecessor == o.predecessor &&
           right_context == o.right_context && guard == o.guard && key == o.key &&
           alternatives == o.alternatives;
  }
};

using LSystemItem = std::variant<Setting, Axiom, SymbolSet, Select, Production>;
struct LSystem {
  Identifier name;
  std::vector<LSystemItem> items;
  SourceSpan span;
  bool operator==(const LSystem& o) const { return name == o.name && items == o.items; }
};

// ---- pieces blocks ----------------------------------------------------------------------------

struct NamedArg {  // radius: 1   or a positional argument (name empty)
  Identifier name;
  Expr value;
  bool operator==(const NamedArg&) const = default;
};
struct Constructor {  // tube(length: 4, taper: 0.85)   mesh("pieces/psi.glb")
  Identifier kind;
  std::vector<NamedArg> args;
  std::optional<std::string> path;  // the string argument of mesh("...")
  SourceSpan span;
  bool operator==(const Constructor& o) const {
    return kind == o.kind && args == o.args && path == o.path;
  }
};
struct RimDecl {    // rim hexagon(radius: 1);
  Identifier name;  // the rim shape's name
  std::vector<NamedArg> args;
  SourceSpan span;
  bool operator==(const RimDecl& o) const { return name == o.name && args == o.args; }
};
struct PieceDecl {  // piece I = tube(length: 4);
  Identifier name;
  Constructor ctor;
  SourceSpan span;
  bool operator==(const PieceDecl& o) const { return name == o.name && ctor == o.ctor; }
};
struct WeightedPiece {
  Identifier piece;
  std::optional<Expr> weight;
  bool operator==(const WeightedPiece&) const = default;
};
struct AttachRule {  // I.top -> I 0.7 | Y 0.3;
  Identifier piece;
  Identifier rim;
  std::vector<WeightedPiece> targets;
  SourceSpan span;
  bool operator==(const AttachRule& o) const {
    return piece == o.piece && rim == o.rim && targets == o.targets;
  }
};
// root I;  twist any;  twist 2;  depth 10;  (a keyword and its values)
struct PieceSetting {
  Identifier key;
  std::vector<Expr> values;  // for root: a NameRef to the piece; for twist: `any` is a NameRef
  SourceSpan span;
  bool operator==(const PieceSetting& o) const { return key == o.key && values == o.values; }
};
using PiecesItem = std::variant<RimDecl, PieceDecl, AttachRule, PieceSetting>;
struct Pieces {
  Identifier name;
  std::vector<PiecesItem> items;
  SourceSpan span;
  bool operator==(const Pieces& o) const { return name == o.name && items == o.items; }
};

// ---- voxels blocks ----------------------------------------------------------------------------

struct VoxelRule {             // 7 -> [0 3 0 7 0 5 0 7] x3;
  Expr parent;                 // a class number
  std::vector<Expr> children;  // eight class numbers, in Morton order (x fastest)
  std::optional<Expr> weight;  // count behind `x`
  SourceSpan span;
  bool operator==(const VoxelRule& o) const {
    return parent == o.parent && children == o.children && weight == o.weight;
  }
};
struct VoxelSetting {  // levels 6;  classes 16;  axiom "oak.axiom.rvx";  seed 3;
  Identifier key;
  std::vector<Expr> values;
  std::optional<std::string> path;
  SourceSpan span;
  bool operator==(const VoxelSetting& o) const {
    return key == o.key && values == o.values && path == o.path;
  }
};
using VoxelsItem = std::variant<VoxelSetting, VoxelRule>;
struct Voxels {
  Identifier name;
  std::vector<VoxelsItem> items;
  SourceSpan span;
  bool operator==(const Voxels& o) const { return name == o.name && items == o.items; }
};

// ---- the file ---------------------------------------------------------------------------------

using Decl = std::variant<Import, ConstDecl, ModuleDecl, LSystem, Pieces, Voxels>;

struct Comment {
  std::string text;  // including the // or /* */ markers
  SourceSpan span;
};

struct File {
  std::uint32_t file_id = 0;  // index in the SourceManager
  std::vector<Decl> decls;
  std::vector<Comment> comments;  // in source order; not part of operator==
  bool operator==(const File& o) const { return decls == o.decls; }
};

}  // namespace ramus::ast
