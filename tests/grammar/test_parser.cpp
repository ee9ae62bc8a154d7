// The parser: every construct of docs/language.md, spans, contextual keywords, the two `|`,
// `->` in guards, error recovery with several errors, nesting limits, binary and empty input.
#include <catch2/catch.hpp>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "grammar/parser.h"

using namespace ramus;

namespace {

struct Parsed {
  SourceManager sm;
  DiagnosticSink diags;
  ast::File file;
  std::string_view slice(const SourceSpan& s) const { return sm.slice(s); }
  std::string errors() const { return render_text(sm, diags.all()); }
};

std::unique_ptr<Parsed> parse_text(std::string text) {
  auto p = std::make_unique<Parsed>();
  std::uint32_t id = p->sm.add("test.ramus", std::move(text));
  p->file = parse(p->sm, id, p->diags);
  return p;
}

template <typename T>
const T& decl(const Parsed& p, std::size_t i) {
  REQUIRE(i < p.file.decls.size());
  REQUIRE(std::holds_alternative<T>(p.file.decls[i]));
  return std::get<T>(p.file.decls[i]);
}

template <typename T, typename Block>
const T& item(const Block& b, std::size_t i) {
  REQUIRE(i < b.items.size());
  REQUIRE(std::holds_alternative<T>(b.items[i]));
  return std::get<T>(b.items[i]);
}

// Fully parenthesized rendering of an expression, to check precedence and associativity.
std::string show(const ast::Expr& e) {
  static const char* bin[] = {"||", "&&", "==", "!=", "<", "<=", ">",
                              ">=", "+",  "-",  "*",  "/", "%",  "^"};
  return std::visit(
      [](const auto& n) -> std::string {
        using T = std::decay_t<decltype(n)>;
        if constexpr (std::is_same_v<T, ast::NumberLit>) {
          return n.text;
        } else if constexpr (std::is_same_v<T, ast::BoolLit>) {
          return n.value ? "true" : "false";
        } else if constexpr (std::is_same_v<T, ast::NameRef>) {
          return n.name;
        } else if constexpr (std::is_same_v<T, ast::Unary>) {
          const char* op = n.op == ast::UnaryOp::Neg ? "-" : n.op == ast::UnaryOp::Plus ? "+" : "!";
          return std::string("(") + op + show(*n.operand) + ")";
        } else if constexpr (std::is_same_v<T, ast::Binary>) {
          return "(" + show(*n.lhs) + " " + bin[int(n.op)] + " " + show(*n.rhs) + ")";
        } else if constexpr (std::is_same_v<T, ast::Conditional>) {
          return "(" + show(*n.cond) + " ? " + show(*n.then_expr) + " : " + show(*n.else_expr) +
                 ")";
        } else {
          std::string s = n.callee.name + "(";
          for (std::size_t i = 0; i < n.args.size(); ++i) s += (i ? ", " : "") + show(n.args[i]);
          return s + ")";
        }
      },
      e.node);
}

std::string show_seq(const ast::ModuleSeq& seq) {
  std::string s;
  for (const auto& m : seq) {
    if (!s.empty()) s += " ";
    s += m.name;
    if (m.has_parens) {
      s += "(";
      for (std::size_t i = 0; i < m.args.size(); ++i) s += (i ? ", " : "") + show(m.args[i]);
      s += ")";
    }
  }
  return s;
}

std::string where(const Parsed& p, std::size_t i) {
  const Diagnostic& d = p.diags.all().at(i);
  LineCol lc = p.sm.line_col(d.span.file, d.span.begin);
  return std::string(info(d.code).id) + "@" + std::to_string(lc.line) + ":" +
         std::to_string(lc.column);
}

const char* kDesignSample = R"(// monopodial tree after ABOP ch. 2
const r1 = 0.9, r2 = 0.6, a0 = 45, a2 = 45, d = 137.5, wr = 0.707;
param seed = 1;

lsystem monopodial {
  derive 10;
  axiom A(1, 10);
  A(l, w)  -> !(w) F(l) [ &(a0) B(l*r2, w*wr) ] /(d) A(l*r1, w*wr);
  B(l, w)  -> !(w) F(l) [ -(a2) $ C(l*r2, w*wr) ] C(l*r1, w*wr);
  C(l, w)  -> !(w) F(l) [ +(a2) $ B(l*r2, w*wr) ] B(l*r1, w*wr);
}

lsystem bush {
  ignore + - F;                                  // for context matching
  axiom F;
  A < B > C : x > 0 -> D(x + 1);                 // context, guard
  F -> (0.33) F[+F]F[-F]F | (0.33) F[+F]F | (0.34) F[-F]F;   // stochastic
  interpret A(l) -> F(l);                        // homomorphism, not derivation
}

pieces almond {
  rim hexagon(radius: 1);                        // the universal rim
  piece I = tube(length: 4, taper: 0.85);        // built-in quad-mesh pieces
  piece Y = fork(angle: 32, taper: 0.8);
  piece P = mesh("pieces/psi.glb");              // external, rims named in the file
  root I;
  I.top -> I 0.7 | Y 0.3;
  Y.left -> I;  Y.right -> I 0.5 | Y 0.5;
  twist any;  depth 10;
}

voxels oak {
  levels 6;  classes 16;                          // 64^3, coefficients quantized to 16 classes
  axiom "oak.axiom.rvx";
  7 -> [0 3 0 7 0 5 0 7] x3;                     // one coarse voxel -> 8 finer, weight 3
}
)";

}  // namespace

TEST_CASE("parser: the design sample parses completely", "[parser]") {
  auto p = parse_text(kDesignSample);
  INFO(p->errors());
  REQUIRE(p->diags.all().empty());
  REQUIRE(p->file.decls.size() == 6);
  const auto& consts = decl<ast::ConstDecl>(*p, 0);
  CHECK_FALSE(consts.is_param);
  CHECK(consts.bindings.size() == 6);
  CHECK(consts.bindings[4].name.name == "d");
  CHECK(show(consts.bindings[4].value) == "137.5");
  CHECK(decl<ast::ConstDecl>(*p, 1).is_param);

  const auto& mono = decl<ast::LSystem>(*p, 2);
  CHECK(mono.name.name == "monopodial");
  REQUIRE(mono.items.size() == 5);
  CHECK(item<ast::Setting>(mono, 0).key.name == "derive");
  CHECK(show_seq(item<ast::Axiom>(mono, 1).modules) == "A(1, 10)");
  const auto& a = item<ast::Production>(mono, 2);
  CHECK(a.predecessor.name == "A");
  CHECK(a.predecessor.params.size() == 2);
  REQUIRE(a.alternatives.size() == 1);
  CHECK_FALSE(a.alternatives[0].probability);
  CHECK(show_seq(a.alternatives[0].successor) ==
        "!(w) F(l) [ &(a0) B((l * r2), (w * wr)) ] /(d) A((l * r1), (w * wr))");
  CHECK(show_seq(item<ast::Production>(mono, 3).alternatives[0].successor) ==
        "!(w) F(l) [ -(a2) $ C((l * r2), (w * wr)) ] C((l * r1), (w * wr))");

  const auto& bush = decl<ast::LSystem>(*p, 3);
  REQUIRE(bush.items.size() == 5);
  const auto& ign = item<ast::SymbolSet>(bush, 0);
  CHECK_FALSE(ign.consider);
  REQUIRE(ign.symbols.size() == 3);
  CHECK(ign.symbols[1].name == "-");
  const auto& ctx = item<ast::Production>(bush, 2);
  REQUIRE(ctx.left_context.size() == 1);
  CHECK(ctx.left_context[0].name == "A");
  CHECK(ctx.predecessor.name == "B");
  REQUIRE(ctx.right_context.size() == 1);
  CHECK(ctx.right_context[0].name == "C");
  REQUIRE(ctx.guard);
  CHECK(show(*ctx.guard) == "(x > 0)");
  const auto& sto = item<ast::Production>(bush, 3);
  REQUIRE(sto.alternatives.size() == 3);
  CHECK(show(*sto.alternatives[2].probability) == "0.34");
  CHECK(show_seq(sto.alternatives[2].successor) == "F [ - F ] F");
  CHECK(item<ast::Production>(bush, 4).kind == ast::ProductionKind::Interpret);

  const auto& pieces = decl<ast::Pieces>(*p, 4);
  REQUIRE(pieces.items.size() == 10);
  const auto& rim = item<ast::RimDecl>(pieces, 0);
  CHECK(rim.name.name == "hexagon");
  CHECK(rim.args.at(0).name.name == "radius");
  const auto& tube = item<ast::PieceDecl>(pieces, 1);
  CHECK(tube.name.name == "I");
  CHECK(tube.ctor.kind.name == "tube");
  CHECK(tube.ctor.args.size() == 2);
  CHECK(item<ast::PieceDecl>(pieces, 3).ctor.path == std::optional<std::string>("pieces/psi.glb"));
  CHECK(item<ast::PieceSetting>(pieces, 4).key.name == "root");
  const auto& top = item<ast::AttachRule>(pieces, 5);
  CHECK(top.piece.name == "I");
  CHECK(top.rim.name == "top");
  REQUIRE(top.targets.size() == 2);
  CHECK(top.targets[1].piece.name == "Y");
  CHECK(show(*top.targets[1].weight) == "0.3");
  CHECK_FALSE(item<ast::AttachRule>(pieces, 6).targets[0].weight);
  CHECK(show(item<ast::PieceSetting>(pieces, 8).values.at(0)) == "any");

  const auto& vox = decl<ast::Voxels>(*p, 5);
  REQUIRE(vox.items.size() == 4);
  CHECK(item<ast::VoxelSetting>(vox, 1).key.name == "classes");
  CHECK(item<ast::VoxelSetting>(vox, 2).path == std::optional<std::string>("oak.axiom.rvx"));
  const auto& rule = item<ast::VoxelRule>(vox, 3);
  CHECK(show(rule.parent) == "7");
  CHECK(rule.children.size() == 8);
  CHECK(show(rule.children[7]) == "7");
  REQUIRE(rule.weight);
  CHECK(show(*rule.weight) == "3");
  CHECK(p->file.comments.size() == 10);
}

TEST_CASE("parser: expression precedence and associativity", "[parser]") {
  auto p = parse_text(
      "const a = 1 + 2 * 3 ^ 2 ^ 3, b = -2 ^ 2, c = a ? 1 : b ? 2 : 3;\n"
      "const d = !x && y || z == 1 < 2, e = 8 - 4 - 2, f = 2 ^ -1 ^ 2, g = (1 + 2) * 3 % 4;\n"
      "const h = sin(30) + max(1, 2 * pi) + uniform(0, 1), i = true != false, j = +x / -y;\n"
      "const k = a <= b && a >= b && a < b && a > b;\n");
  INFO(p->errors());
  REQUIRE(p->diags.all().empty());
  const auto& c0 = decl<ast::ConstDecl>(*p, 0).bindings;
  CHECK(show(c0[0].value) == "(1 + (2 * (3 ^ (2 ^ 3))))");
  CHECK(show(c0[1].value) == "(-(2 ^ 2))");
  CHECK(show(c0[2].value) == "(a ? 1 : (b ? 2 : 3))");
  const auto& c1 = decl<ast::ConstDecl>(*p, 1).bindings;
  CHECK(show(c1[0].value) == "(((!x) && y) || (z == (1 < 2)))");
  CHECK(show(c1[1].value) == "((8 - 4) - 2)");
  CHECK(show(c1[2].value) == "(2 ^ (-(1 ^ 2)))");
  CHECK(show(c1[3].value) == "(((1 + 2) * 3) % 4)");
  CHECK(c1[3].value.parenthesized == false);
  const auto& c2 = decl<ast::ConstDecl>(*p, 2).bindings;
  CHECK(show(c2[0].value) == "((sin(30) + max(1, (2 * pi))) + uniform(0, 1))");
  CHECK(show(c2[1].value) == "(true != false)");
  CHECK(show(c2[2].value) == "((+x) / (-y))");
  CHECK(show(decl<ast::ConstDecl>(*p, 3).bindings[0].value) ==
        "((((a <= b) && (a >= b)) && (a < b)) && (a > b))");
}

TEST_CASE("parser: numbers keep their text and value", "[parser]") {
  auto p = parse_text("const a = 12, b = 0.50, c = .5, d = 1e-3, e2 = 2.5E+2, f = 1.;");
  REQUIRE(p->diags.all().empty());
  const auto& bs = decl<ast::ConstDecl>(*p, 0).bindings;
  auto num = [&](std::size_t i) { return std::get<ast::NumberLit>(bs[i].value.node); };
  CHECK(num(0).value == 12);
  CHECK(num(1).text == "0.50");
  CHECK(num(1).value == 0.5);
  CHECK(num(2).value == 0.5);
  CHECK(num(3).value == Approx(1e-3));
  CHECK(num(4).value == 250);
  CHECK(num(5).value == 1);
}

TEST_CASE("parser: every node has the span of its text", "[parser][spans]") {
  auto p = parse_text("const a = 1 + 2*3;\nlsystem x {\n  A(l) : l > 1 -> B(l - 1) C;\n}\n");
  REQUIRE(p->diags.all().empty());
  const auto& cd = decl<ast::ConstDecl>(*p, 0);
  CHECK(p->slice(cd.span) == "const a = 1 + 2*3;");
  CHECK(p->slice(cd.bindings[0].name.span) == "a");
  CHECK(p->slice(cd.bindings[0].value.span) == "1 + 2*3");
  const auto& bin = std::get<ast::Binary>(cd.bindings[0].value.node);
  CHECK(p->slice(bin.rhs->span) == "2*3");
  const auto& ls = decl<ast::LSystem>(*p, 1);
  CHECK(p->slice(ls.span) == "lsystem x {\n  A(l) : l > 1 -> B(l - 1) C;\n}");
  CHECK(p->slice(ls.name.span) == "x");
  const auto& pr = item<ast::Production>(ls, 0);
  CHECK(p->slice(pr.span) == "A(l) : l > 1 -> B(l - 1) C;");
  CHECK(p->slice(pr.predecessor.span) == "A(l)");
  CHECK(p->slice(pr.predecessor.params[0].span) == "l");
  CHECK(p->slice(pr.guard->span) == "l > 1");
  CHECK(p->slice(pr.alternatives[0].span) == "B(l - 1) C");
  CHECK(p->slice(pr.alternatives[0].successor[0].span) == "B(l - 1)");
  CHECK(p->slice(pr.alternatives[0].successor[0].args[0].span) == "l - 1");
  CHECK(p->slice(pr.alternatives[0].successor[1].span) == "C");
  LineCol lc = p->sm.line_col(0, pr.span.begin);
  CHECK(lc.line == 3);
  CHECK(lc.column == 3);
}

TEST_CASE("parser: keywords are contextual", "[parser]") {
  auto p = parse_text(
      "param seed = 1;\nconst axiom = 2, derive = 3;\n"
      "lsystem seed {\n  seed seed;\n  derive derive;\n  axiom axiom;\n  axiom -> F;\n"
      "  interpret -> G;\n  interpret interpret -> H;\n  decompose A -> B;\n  select nearest(x);\n"
      "  select(x) -> X;\n}\n");
  INFO(p->errors());
  REQUIRE(p->diags.all().empty());
  CHECK(decl<ast::ConstDecl>(*p, 0).bindings[0].name.name == "seed");
  const auto& ls = decl<ast::LSystem>(*p, 2);
  REQUIRE(ls.items.size() == 9);
  CHECK(item<ast::Setting>(ls, 0).key.name == "seed");
  CHECK(show(item<ast::Setting>(ls, 1).values[0]) == "derive");
  CHECK(item<ast::Axiom>(ls, 2).modules.at(0).name == "axiom");
  CHECK(item<ast::Production>(ls, 3).predecessor.name == "axiom");
  const auto& i1 = item<ast::Production>(ls, 4);
  CHECK(i1.kind == ast::ProductionKind::Rewrite);
  CHECK(i1.predecessor.name == "interpret");
  const auto& i2 = item<ast::Production>(ls, 5);
  CHECK(i2.kind == ast::ProductionKind::Interpret);
  CHECK(i2.predecessor.name == "interpret");
  CHECK(item<ast::Production>(ls, 6).kind == ast::ProductionKind::Decompose);
  const auto& sel = item<ast::Select>(ls, 7);
  CHECK(sel.mode.name == "nearest");
  CHECK(sel.keys.size() == 1);
  CHECK(item<ast::Production>(ls, 8).predecessor.name == "select");
}

TEST_CASE("parser: stochastic separator versus the turtle symbol |", "[parser]") {
  auto p = parse_text(
      "lsystem s {\n  A -> (0.5) F | G | (0.5) H |;\n  B -> F | F;\n  C -> ;\n"
      "  D -> (0.25)|(0.75) [ | ];\n}\n");
  INFO(p->errors());
  REQUIRE(p->diags.all().empty());
  const auto& ls = decl<ast::LSystem>(*p, 0);
  const auto& a = item<ast::Production>(ls, 0);
  REQUIRE(a.alternatives.size() == 2);
  CHECK(show_seq(a.alternatives[0].successor) == "F | G");
  CHECK(show_seq(a.alternatives[1].successor) == "H |");
  const auto& b = item<ast::Production>(ls, 1);
  REQUIRE(b.alternatives.size() == 1);
  CHECK_FALSE(b.alternatives[0].probability);
  CHECK(show_seq(b.alternatives[0].successor) == "F | F");
  CHECK(item<ast::Production>(ls, 2).alternatives.at(0).successor.empty());
  const auto& d = item<ast::Production>(ls, 3);
  REQUIRE(d.alternatives.size() == 2);
  CHECK(d.alternatives[0].successor.empty());
  CHECK(show_seq(d.alternatives[1].successor) == "[ | ]");
}

TEST_CASE("parser: the arrow is never minus in guards", "[parser]") {
  auto p = parse_text(
      "lsystem g {\n  A(x) : x > 0 -> B(x - 1);\n  A(x) : x-1 < 2 -> -(30) B;\n"
      "  A(x) : x ->-F;\n  A(x) : -x > -1 -> - - F;\n  F > F -> F-F;\n}\n");
  INFO(p->errors());
  REQUIRE(p->diags.all().empty());
  const auto& ls = decl<ast::LSystem>(*p, 0);
  CHECK(show(*item<ast::Production>(ls, 0).guard) == "(x > 0)");
  const auto& b = item<ast::Production>(ls, 1);
  CHECK(show(*b.guard) == "((x - 1) < 2)");
  CHECK(show_seq(b.alternatives[0].successor) == "-(30) B");
  const auto& c = item<ast::Production>(ls, 2);
  CHECK(show(*c.guard) == "x");
  CHECK(show_seq(c.alternatives[0].successor) == "- F");
  const auto& d = item<ast::Production>(ls, 3);
  CHECK(show(*d.guard) == "((-x) > (-1))");
  CHECK(show_seq(d.alternatives[0].successor) == "- - F");
  const auto& e = item<ast::Production>(ls, 4);
  CHECK(e.right_context.at(0).name == "F");
  CHECK(show_seq(e.alternatives[0].successor) == "F - F");
}

TEST_CASE("parser: contexts, turtle symbols and names as written", "[parser]") {
  auto p = parse_text(
      "module Apex, S_1(a, b), X();\nimport trees.oak;\nimport \"lib/my.ramus\";\n"
      "lsystem c {\n  consider A B [ ];\n  A B(x) < C(y) > [ D ] E : x < y -> FF AB(1) \\(10) /(5)"
      " & ^ ' ~(2) % ! $ + -;\n  ignore | ~;\n}\n");
  INFO(p->errors());
  REQUIRE(p->diags.all().empty());
  const auto& md = decl<ast::ModuleDecl>(*p, 0);
  REQUIRE(md.modules.size() == 3);
  CHECK(md.modules[1].name == "S_1");
  CHECK(md.modules[1].params.size() == 2);
  CHECK(md.modules[2].has_parens);
  CHECK(md.modules[2].params.empty());
  CHECK_FALSE(md.modules[0].has_parens);
  const auto& im = decl<ast::Import>(*p, 1);
  CHECK(im.path == "trees.oak");
  CHECK_FALSE(im.is_file);
  CHECK(decl<ast::Import>(*p, 2).is_file);
  CHECK(decl<ast::Import>(*p, 2).path == "lib/my.ramus");
  const auto& ls = decl<ast::LSystem>(*p, 3);
  const auto& con = item<ast::SymbolSet>(ls, 0);
  CHECK(con.consider);
  CHECK(con.symbols.size() == 4);
  const auto& pr = item<ast::Production>(ls, 1);
  REQUIRE(pr.left_context.size() == 2);
  CHECK(pr.left_context[1].params.at(0).name == "x");
  CHECK(pr.predecessor.name == "C");
  REQUIRE(pr.right_context.size() == 4);
  CHECK(pr.right_context[0].name == "[");
  CHECK(pr.right_context[2].name == "]");
  CHECK(show_seq(pr.alternatives[0].successor) == "FF AB(1) \\(10) /(5) & ^ ' ~(2) % ! $ + -");
  CHECK(item<ast::SymbolSet>(ls, 2).symbols.at(0).name == "|");
}

TEST_CASE("parser: comments are collected with spans", "[parser]") {
  auto p = parse_text(
      "// head\nconst a = 1; /* block\n more */ const s = 2; // tail\n"
      "import \"not // a comment\";");
  REQUIRE(p->diags.all().empty());
  REQUIRE(p->file.comments.size() == 3);
  CHECK(p->file.comments[0].text == "// head");
  CHECK(p->file.comments[1].text == "/* block\n more */");
  CHECK(p->slice(p->file.comments[2].span) == "// tail");
  CHECK(decl<ast::Import>(*p, 2).path == "not // a comment");
}

TEST_CASE("parser: empty and comment-only files give an empty AST", "[parser]") {
  auto p = parse_text("");
  CHECK(p->diags.all().empty());
  CHECK(p->file.decls.empty());
  auto q = parse_text("  // nothing\n\n/* here */\n");
  CHECK(q->diags.all().empty());
  CHECK(q->file.decls.empty());
  CHECK(q->file.comments.size() == 2);
  auto bom = parse_text(
      "\xEF\xBB\xBF"
      "const a = 1;");
  CHECK(bom->diags.all().empty());
  CHECK(bom->file.decls.size() == 1);
}

TEST_CASE("parser: binary input gives E0002", "[parser][bad-input]") {
  auto p = parse_text(std::string("const a = 1;\n\0\x01\x02garbage", 22));
  REQUIRE(p->diags.all().size() == 1);
  CHECK(where(*p, 0) == "E0002@2:1");
  CHECK(p->file.decls.empty());
  auto q = parse_text("const a = \xff\xfe;");
  REQUIRE(q->diags.all().size() == 1);
  CHECK(where(*q, 0) == "E0002@1:11");
  CHECK(q->diags.all()[0].message.find("0xFF") != std::string::npos);
  // Valid UTF-8 outside the grammar is a syntax error, not binary input.
  auto r = parse_text("const \xC3\xA9 = 1; // caf\xC3\xA9");
  REQUIRE(r->diags.all().size() == 1);
  CHECK(where(*r, 0) == "E0003@1:7");
}

TEST_CASE("parser: several errors are each reported at their line and column",
          "[parser][recovery]") {
  auto p = parse_text(
      "const a = 1\n"                            // 1: missing ;
      "const b = ;\n"                            // 2: expected expression at ;
      "lsystem x {\n"                            // 3
      "  axiom A;\n"                             // 4
      "  A -> B(1 2);\n"                         // 5: expected ')' at 2
      "  B -> (0.5 C;\n"                         // 6: expected ')' at C
      "  -> C;\n"                                // 7: no item starts with ->
      "  C -> D;\n"                              // 8: fine
      "}\n"                                      // 9
      "pieces p { rim r(radius 1); root I; }\n"  // 10: expected ')' at 1
      "voxels v { 1 -> [1 2] x ; levels 3; }\n"  // 11: expected expression after x
      "oops;\n");                                // 12: not a declaration
  INFO(p->errors());
  const auto& ds = p->diags.all();
  REQUIRE(ds.size() == 8);
  CHECK(where(*p, 0) == "E0003@1:12");
  CHECK(ds[0].message == "expected ';'");
  CHECK(where(*p, 1) == "E0003@2:11");
  CHECK(ds[1].message == "expected expression");
  CHECK(where(*p, 2) == "E0003@5:12");
  CHECK(ds[2].message == "expected ')'");
  CHECK(where(*p, 3) == "E0003@6:13");
  CHECK(where(*p, 4) == "E0003@7:3");
  CHECK(where(*p, 5) == "E0003@10:25");
  CHECK(where(*p, 6) == "E0003@11:25");
  CHECK(where(*p, 7) == "E0003@12:1");
  // What parsed around the errors is kept.
  const auto& ls = decl<ast::LSystem>(*p, 0);
  REQUIRE(ls.items.size() == 2);
  CHECK(item<ast::Production>(ls, 1).predecessor.name == "C");
  const auto& pc = decl<ast::Pieces>(*p, 1);
  REQUIRE(pc.items.size() == 1);
  CHECK(item<ast::PieceSetting>(pc, 0).key.name == "root");
  const auto& vx = decl<ast::Voxels>(*p, 2);
  REQUIRE(vx.items.size() == 1);
}

TEST_CASE("parser: a missing closing brace and a broken block header", "[parser][recovery]") {
  auto p = parse_text("lsystem {\n  A -> B;\n}\nconst a = 1;\nlsystem y {\n  A -> B;\n");
  INFO(p->errors());
  REQUIRE(p->diags.all().size() == 2);
  CHECK(where(*p, 0) == "E0003@1:9");
  CHECK(p->diags.all()[0].message == "expected identifier");
  CHECK(where(*p, 1) == "E0003@6:10");
  CHECK(p->diags.all()[1].notes.size() == 1);
  REQUIRE(p->file.decls.size() == 2);
  CHECK(decl<ast::LSystem>(*p, 1).items.size() == 1);
}

TEST_CASE("parser: unterminated comment and string", "[parser][recovery]") {
  auto p = parse_text("const a = 1;\n/* never closed\nconst b = 2;");
  REQUIRE(p->diags.all().size() == 1);
  CHECK(where(*p, 0) == "E0005@2:1");
  CHECK(p->file.decls.size() == 1);
  auto q = parse_text("import \"abc\nconst b = 2;");
  REQUIRE(q->diags.all().size() == 1);
  CHECK(where(*q, 0) == "E0003@1:12");
  CHECK(q->diags.all()[0].message == "expected '\"'");
}

TEST_CASE("parser: deep nesting gives E0004 and no stack overflow", "[parser][bad-input]") {
  auto expect_deep = [](const std::string& text, std::size_t decls) {
    auto p = parse_text(text);
    INFO(text.substr(0, 60));
    REQUIRE(p->diags.all().size() == 1);
    CHECK(info(p->diags.all()[0].code).id == std::string("E0004"));
    CHECK(p->file.decls.size() == decls);
  };
  // Brackets: caught by the pre-scan.
  expect_deep("const a = " + std::string(100000, '(') + "1;", 0);
  expect_deep("lsystem x { A -> " + std::string(130, '[') + "; }", 0);
  // Operator chains build deep trees without brackets; each is reported, the rest parses.
  expect_deep("const a = " + std::string(100000, '-') + "1;\nconst b = 2;", 1);
  std::string sum = "1";
  for (int i = 0; i < 5000; ++i) sum += "+1";
  expect_deep("const a = " + sum + ";\nconst b = 2;", 1);
  std::string pow = "2";
  for (int i = 0; i < 5000; ++i) pow += "^2";
  expect_deep("const a = " + pow + ";\nconst b = 2;", 1);
  std::string cond = "x";
  for (int i = 0; i < 5000; ++i) cond += " ? 1 : x";
  expect_deep("const a = " + cond + ";\nconst b = 2;", 1);
  std::string then = "";
  for (int i = 0; i < 5000; ++i) then += "x ? ";
  expect_deep("const a = " + then + "1;\nconst b = 2;", 1);
  expect_deep("const a = " + std::string(129, '(') + "1" + std::string(129, ')') + ";", 0);
  std::string calls = "1";
  for (int i = 0; i < 130; ++i) calls = "sin(" + calls + ")";
  expect_deep("const a = x;\nconst b = " + calls + ";\nconst c = 2;", 2);
  // Just under the limit is fine.
  std::string ok = "1";
  for (int i = 0; i < 100; ++i) ok += "+1";
  auto p = parse_text("const a = " + std::string(120, '(') + ok + std::string(120, ')') + ";");
  INFO(p->errors());
  CHECK(p->diags.all().empty());
  std::string nested = "1";
  for (int i = 0; i < 120; ++i) nested = "sin(" + nested + ")";
  auto q = parse_text("lsystem s { axiom F(" + nested + ") " + std::string(120, '[') + "F" +
                      std::string(120, ']') + "; }");
  INFO(q->errors());
  CHECK(q->diags.all().empty());
}

TEST_CASE("parser: the examples of docs/language.md parse without errors", "[parser][docs]") {
  std::ifstream in(std::string(RAMUS_SOURCE_DIR) + "/docs/language.md");
  REQUIRE(in);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string doc = ss.str();
  int blocks = 0;
  for (std::size_t p = doc.find("```ramus\n"); p != std::string::npos;
       p = doc.find("```ramus\n", p + 1)) {
    std::size_t b = p + 9, e = doc.find("```", b);
    REQUIRE(e != std::string::npos);
    auto parsed = parse_text(doc.substr(b, e - b));
    INFO(parsed->errors());
    CHECK(parsed->diags.all().empty());
    CHECK(!parsed->file.decls.empty());
    ++blocks;
  }
  CHECK(blocks >= 1);
}
