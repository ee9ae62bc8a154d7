// The formatter (grammar/format.h): the canonical layout, comments kept, idempotence, and the
// round trip over every .ramus file in examples/ and stdlib/.
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "grammar/format.h"
#include "grammar/parser.h"

using namespace ramus;

namespace {

struct Parsed {
  SourceManager sm;
  ast::File file;
  bool ok = false;
  std::string errors;
};

std::unique_ptr<Parsed> parse_text(const std::string& name, const std::string& text) {
  auto p = std::make_unique<Parsed>();
  DiagnosticSink sink;
  std::uint32_t id = p->sm.add(name, text);
  p->file = parse(p->sm, id, sink);
  p->ok = !sink.has_errors();
  p->errors = render_text(p->sm, sink.all());
  return p;
}

std::string fmt(const std::string& text) {
  auto p = parse_text("t.ramus", text);
  INFO(p->errors);
  REQUIRE(p->ok);
  return format_file(p->file, p->sm);
}

std::vector<std::string> comment_texts(const ast::File& f) {
  std::vector<std::string> out;
  for (const ast::Comment& c : f.comments) {
    std::string t = c.text;
    while (!t.empty() && (t.back() == ' ' || t.back() == '\r' || t.back() == '\n')) t.pop_back();
    out.push_back(t);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// fmt(fmt(x)) == fmt(x), the AST of fmt(x) equals the AST of x, and no comment is lost.
void check_round_trip(const std::string& name, const std::string& text) {
  INFO(name);
  auto original = parse_text(name, text);
  INFO(original->errors);
  REQUIRE(original->ok);
  std::string once = format_file(original->file, original->sm);
  auto again = parse_text(name, once);
  INFO(once);
  INFO(again->errors);
  REQUIRE(again->ok);
  CHECK(again->file == original->file);
  CHECK(comment_texts(again->file) == comment_texts(original->file));
  CHECK(format_file(again->file, again->sm) == once);
}

}  // namespace

TEST_CASE("format: the canonical layout", "[format]") {
  const char* in =
      "const r1=0.9,r2 = .60 ;param   n=3;\n"
      "module A(l,w),Apex;\n"
      "lsystem   m{derive n;axiom A(1,10);A(l,w)->!(w)F(l)[&(45)B(l*r2,w*0.707)]/(137.5)A(l*r1,w);"
      "F->(0.5)F[+F]F|(0.5)FF;interpret B(l,w)->F(l);A < B(x) > [C] : x>1&&!(x==2) -> ;}\n";
  const char* out =
      "const r1 = 0.9, r2 = .60;\n"
      "param n = 3;\n"
      "module A(l, w), Apex;\n"
      "lsystem m {\n"
      "  derive n;\n"
      "  axiom A(1, 10);\n"
      "  A(l, w) -> !(w)F(l)[&(45)B(l * r2, w * 0.707)]/(137.5)A(l * r1, w);\n"
      "  F -> (0.5) F[+F]F\n"
      "      | (0.5) FF;\n"
      "  interpret B(l, w) -> F(l);\n"
      "  A < B(x) > [C] : x > 1 && !(x == 2) ->;\n"
      "}\n";
  CHECK(fmt(in) == out);
  CHECK(fmt(out) == out);
}

TEST_CASE("format: names stay as written and modules are split only where names merge",
          "[format]") {
  CHECK(fmt("lsystem s { axiom F F FF  A B(1)C [ + F ] / /(2); }") ==
        "lsystem s {\n  axiom F F FF A B(1)C[+F]/ /(2);\n}\n");
}

TEST_CASE("format: parentheses where written or needed and none added otherwise", "[format]") {
  CHECK(fmt("const a = (1 + 2) * 3, b = 1 + (2 * 3), c = 2 ^ -1, d = -(2 ^ 2);") ==
        "const a = (1 + 2) * 3, b = 1 + (2 * 3), c = 2 ^ -1, d = -(2 ^ 2);\n");
  CHECK(fmt("const a = 1?2:3, b = (1 ? 2 : 3) + 1;") ==
        "const a = 1 ? 2 : 3, b = (1 ? 2 : 3) + 1;\n");
}

TEST_CASE("format: comments stay at their places", "[format]") {
  const char* in =
      "// header\n"
      "\n"
      "\n"
      "const a = 1;   // trailing\n"
      "/* before */ const b = 2;\n"
      "lsystem s {  // on the brace line\n"
      "  // leading\n"
      "  axiom F;\n"
      "  F -> (0.5) F // first\n"
      "     | (0.5) FF; // last\n"
      "  // at the end\n"
      "}\n"
      "// tail\n";
  const char* out =
      "// header\n"
      "\n"
      "const a = 1;  // trailing\n"
      "/* before */\n"
      "const b = 2;\n"
      "lsystem s {  // on the brace line\n"
      "  // leading\n"
      "  axiom F;\n"
      "  F -> (0.5) F  // first\n"
      "      | (0.5) FF;  // last\n"
      "  // at the end\n"
      "}\n"
      "// tail\n";
  CHECK(fmt(in) == out);
  CHECK(fmt(out) == out);
}

TEST_CASE("format: pieces and voxels blocks", "[format]") {
  const char* in =
      "pieces almond{rim hexagon(radius:1);piece I=tube(length:4,taper:0.85);"
      "piece P=mesh(\"pieces/psi.glb\");root I;I.top->I 0.7|P 0.3;twist any;depth 10;}\n"
      "voxels oak{levels 6;classes 16;axiom \"oak.axiom.rvx\";7->[0 3 0 7 0 5 0 7]x3;}\n";
  const char* out =
      "pieces almond {\n"
      "  rim hexagon(radius: 1);\n"
      "  piece I = tube(length: 4, taper: 0.85);\n"
      "  piece P = mesh(\"pieces/psi.glb\");\n"
      "  root I;\n"
      "  I.top -> I 0.7 | P 0.3;\n"
      "  twist any;\n"
      "  depth 10;\n"
      "}\n"
      "voxels oak {\n"
      "  levels 6;\n"
      "  classes 16;\n"
      "  axiom \"oak.axiom.rvx\";\n"
      "  7 -> [0 3 0 7 0 5 0 7] x3;\n"
      "}\n";
  CHECK(fmt(in) == out);
  CHECK(fmt(out) == out);
}

TEST_CASE("format: voxel children that are names stay apart from a parenthesised one", "[format]") {
  // `h 0>=1` are two children; printed `h (0 >= 1)` they would read as the call `h(0 >= 1)`, so
  // `h` is parenthesised, and then so is the name before it (found by fuzz_check_format).
  const char* in = "voxels v{0->[0 3 s h 0>=1 1 1 1];}\n";
  const char* out =
      "voxels v {\n"
      "  0 -> [0 3 (s) (h) (0 >= 1) 1 1 1];\n"
      "}\n";
  CHECK(fmt(in) == out);
  CHECK(fmt(out) == out);
}

TEST_CASE("format: a file without source text", "[format]") {
  auto p = parse_text("t.ramus", "const a = 1; lsystem s { axiom F; } lsystem t { axiom F; }");
  REQUIRE(p->ok);
  CHECK(format_file(p->file) ==
        "const a = 1;\n\nlsystem s {\n  axiom F;\n}\n\nlsystem t {\n  axiom F;\n}\n");
}

TEST_CASE("format: round trip over examples and stdlib", "[format]") {
  namespace fs = std::filesystem;
  int files = 0;
  for (const char* dir : {"examples", "stdlib"}) {
    fs::path root = fs::path(RAMUS_SOURCE_DIR) / dir;
    if (!fs::exists(root)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
      if (entry.path().extension() != ".ramus") continue;
      std::ifstream in(entry.path(), std::ios::binary);
      std::stringstream ss;
      ss << in.rdbuf();
      check_round_trip(entry.path().string(), ss.str());
      ++files;
    }
  }
  CHECK(files > 0);
}

TEST_CASE("format: round trip over the golden formatter inputs", "[format]") {
  namespace fs = std::filesystem;
  fs::path root = fs::path(RAMUS_SOURCE_DIR) / "tests/golden/fmt";
  int files = 0;
  for (const auto& entry : fs::directory_iterator(root)) {
    if (entry.path().extension() != ".ramus") continue;
    std::ifstream in(entry.path(), std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    check_round_trip(entry.path().string(), ss.str());
    ++files;
  }
  CHECK(files > 0);
}

TEST_CASE("format: long successors break between modules before a branch", "[format]") {
  std::string succ;
  for (int i = 0; i < 8; ++i) succ += "F(length * 0.5)[+(angle)G(length)]";
  std::string out = fmt("lsystem s { axiom F; F -> " + succ + "; }");
  const char* want =
      "lsystem s {\n"
      "  axiom F;\n"
      "  F -> F(length * 0.5)[+(angle)G(length)]F(length * 0.5)[+(angle)G(length)]F(length * 0.5)\n"
      "        [+(angle)G(length)]F(length * 0.5)[+(angle)G(length)]F(length * 0.5)\n"
      "        [+(angle)G(length)]F(length * 0.5)[+(angle)G(length)]F(length * 0.5)\n"
      "        [+(angle)G(length)]F(length * 0.5)[+(angle)G(length)];\n"
      "}\n";
  CHECK(out == want);
  CHECK(fmt(out) == out);
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);) CHECK(line.size() <= 100);
}

TEST_CASE("format: ABOP polygons { . } and a block's closing brace", "[format]") {
  CHECK(fmt("lsystem s { axiom [A][B]; A -> [ +A { . ] . C . } ; B -> B&.G.}; }") ==
        "lsystem s {\n  axiom [A][B];\n  A -> [+A{.].C.};\n  B -> B&.G.};\n}\n");
  check_round_trip("polygons.ramus",
                   "lsystem s { axiom {.A(0)}; A(t) -> G(5, 1)[-B(t).][A(t + 1)][+B(t).]; }\n");
  // A `}` before the end of the file or a declaration closes the block, so a missing `;` is
  // still reported as such.
  auto p = parse_text("t.ramus", "lsystem s {\n  axiom F;\n  F -> FF\n}\nlsystem t { axiom F; }\n");
  CHECK_FALSE(p->ok);
  CHECK(p->errors.find("t.ramus:3:10: error[E0003]: expected ';'") != std::string::npos);
}
