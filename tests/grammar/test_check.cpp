// The semantic checks (grammar/check*.cpp): each check on a small grammar, at the right place.
#include <time.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <string>
#include <vector>

#include "grammar/check.h"
#include "grammar/loader.h"

using namespace ramus;

namespace {

struct Found {
  std::string code;  // "E0101"
  std::uint32_t line, column;
  std::string message;
};

std::vector<Found> check_text(const std::string& text, const CheckOptions& options = {}) {
  SourceManager sm;
  DiagnosticSink sink;
  Program p = load_program_text("t.ramus", text, sm, sink);
  REQUIRE_FALSE(sink.has_errors());  // the snippets parse
  check_program(p, sm, sink, options);
  sink.sort();
  std::vector<Found> out;
  for (const Diagnostic& d : sink.all()) {
    LineCol lc = sm.line_col(d.span.file, d.span.begin);
    out.push_back({info(d.code).id, lc.line, lc.column, d.message});
  }
  return out;
}

std::string codes(const std::vector<Found>& fs) {
  std::string s;
  for (const Found& f : fs) {
    s += (s.empty() ? "" : " ") + f.code + "@" + std::to_string(f.line) + ":" +
         std::to_string(f.column);
  }
  return s;
}

std::string codes_of(const std::string& text) { return codes(check_text(text)); }

}  // namespace

TEST_CASE("check: a correct grammar gives no diagnostics", "[check]") {
  const char* text = R"(// monopodial tree after ABOP ch. 2
const r1 = 0.9, r2 = 0.6, a0 = 45, a2 = 45, d = 137.5, wr = 0.707;
param n = 10;
lsystem monopodial {
  derive n;
  angle 30;
  tropism 0, 0, -1;
  axiom A(1, 10);
  A(l, w) -> !(w) F(l) [ &(a0) B(l*r2, w*wr) ] /(d) A(l*r1, w*wr);
  B(l, w) -> !(w) F(l) [ -(a2) $ C(l*r2, w*wr) ] C(l*r1, w*wr);
  C(l, w) -> !(w) F(l) [ +(a2) $ B(l*r2, w*wr) ] B(l*r1, w*wr);
}
lsystem bush {
  ignore + - F;
  axiom F A(1) B C;
  A(x) < B > C : x > 0 && true -> D(x + 1) FF;
  F -> (0.33) F[+F]F[-F]F | (0.33) F[+F]F | (0.34) F[-F]F;
  interpret D(l) -> F(l);
}
)";
  CHECK(codes_of(text) == "");
}

TEST_CASE("check: module names with digits must be declared", "[check]") {
  CHECK(codes_of("lsystem a { axiom S_1; }") == "E0101@1:19");
  CHECK(codes_of("module S_1; lsystem a { axiom S_1; }") == "");
  // Letters only: one module per letter, FF is F F.
  CHECK(codes_of("lsystem a { axiom FF AB(1) B(2); }") == "");
  CHECK(codes_of("lsystem a { ignore N2; axiom F; }") == "E0101@1:20");
}

TEST_CASE("check: module arity agrees with the declaration and with earlier uses", "[check]") {
  CHECK(codes_of("module A(x);\nlsystem a { axiom A(1, 2); }") == "E0102@2:19");
  CHECK(codes_of("lsystem a { axiom A(1) B; B -> A; }") == "E0102@1:32");
  CHECK(codes_of("lsystem a { axiom F(1) [ ] +; }") == "");
  CHECK(codes_of("lsystem a { axiom [(1)]; }") == "E0102@1:19");
  CHECK(codes_of("lsystem a { axiom F(1, 2); }") == "E0102@1:19");
}

TEST_CASE("check: a predecessor of several letters must be declared", "[check]") {
  CHECK(codes_of("lsystem a { axiom A B; AB -> F; }") == "E0109@1:24");
  CHECK(codes_of("module AB; lsystem a { axiom AB; AB -> F; }") == "");
}

TEST_CASE("check: unknown names and functions", "[check]") {
  CHECK(codes_of("const a = b;") == "E0104@1:11");
  CHECK(codes_of("lsystem s { axiom A(1); A(x) -> A(y); }") == "E0104@1:35");
  CHECK(codes_of("lsystem s { axiom A(sine(1)); }") == "E0105@1:21");
  CHECK(codes_of("lsystem s { axiom A(sin(1, 2)); }") == "E0106@1:21");
  CHECK(codes_of("lsystem s { axiom A(pi * e); }") == "");
}

TEST_CASE("check: duplicate definitions point at the first one", "[check]") {
  auto fs = check_text("const a = 1;\nconst a = 2;\nlsystem s { axiom A(a); }");
  REQUIRE(codes(fs) == "E0103@2:7");
  CHECK(codes_of("module A, A;") == "E0103@1:11");
  CHECK(codes_of("lsystem s { axiom F; } voxels s { levels 2; }") == "E0103@1:31");
  CHECK(codes_of("lsystem s { derive 1; derive 2; axiom F; }") == "E0103@1:23");
  CHECK(codes_of("lsystem s { axiom A(1, 2); A(x, y) < A(x, z) -> F; }") == "E0103@1:40");
  CHECK(codes_of("pieces p { piece I = tube(); piece I = tube(); root I; }") == "E0103@1:36");
}

TEST_CASE("check: constants may only use earlier constants", "[check]") {
  CHECK(codes_of("const a = b, b = 1;\nlsystem s { axiom A(a); }") == "E0110@1:11");
  CHECK(codes_of("const a = a;\nlsystem s { axiom A(a); }") == "E0110@1:11");
  CHECK(codes_of("const a = uniform(0, 1);\nlsystem s { axiom A(a); }") == "E0208@1:11");
  CHECK(codes_of("const a = 1 / 0;\nlsystem s { axiom A(a); }") == "E0209@1:11");
}

TEST_CASE("check: booleans and numbers do not mix", "[check]") {
  CHECK(codes_of("lsystem s { axiom A(1); A(x) : x + 1 -> B; }") == "E0203@1:32");
  CHECK(codes_of("lsystem s { axiom A(1); A(x) : x > 1 && x -> B; }") == "E0202@1:41");
  CHECK(codes_of("lsystem s { axiom A(true); }") == "E0204@1:21");
  CHECK(codes_of("lsystem s { axiom A(true + 1); }") == "E0201@1:21");
  CHECK(codes_of("lsystem s { axiom A(1 == true ? 1 : 2); }") == "E0205@1:26");
  CHECK(codes_of("lsystem s { axiom A(1 ? 1 : 2); }") == "E0203@1:21");
  CHECK(codes_of("const big = true;\nlsystem s { axiom A(1); A(x) : big -> B; }") == "");
}

TEST_CASE("check: probabilities between 0 and 1 that sum to 1", "[check]") {
  CHECK(codes_of("lsystem s { axiom F; F -> (0.5) F | (0.6) FF; }") == "E0207@1:27");
  CHECK(codes_of("lsystem s { axiom F; F -> (1.5) F | (-0.5) FF; }") == "E0206@1:28 E0206@1:38");
  // 0.1 + 0.2 + 0.7 is not exactly 1 in doubles: the tolerance is 1e-9.
  CHECK(codes_of("lsystem s { axiom F; F -> (0.1) F | (0.2) FF | (0.7) FFF; }") == "");
  // Not foldable (a parameter): not checked.
  CHECK(codes_of("lsystem s { axiom A(1); A(p) -> (p) A(p) | (0.5) B; }") == "");
}

TEST_CASE("check: lsystem settings", "[check]") {
  CHECK(codes_of("lsystem s { derive -1; axiom F; }") == "E0301@1:20");
  CHECK(codes_of("lsystem s { derive 2.5; axiom F; }") == "E0301@1:20");
  CHECK(codes_of("lsystem s { derivation 2; axiom F; }") == "E0302@1:13");
  CHECK(codes_of("lsystem s { tropism 0, 1; axiom F; }") == "E0303@1:13");
  CHECK(codes_of("lsystem s { angle uniform(1, 2); axiom F; }") == "E0208@1:19");
  CHECK(codes_of("lsystem s { derive 1; }") == "E0305@1:9");
  CHECK(codes_of("lsystem s { axiom F; axiom A; }") == "E0304@1:22");
  CHECK(codes_of("lsystem s { select closest(1); axiom F; }") == "E0306@1:20");
}

TEST_CASE("check: -D values reach the folded settings", "[check]") {
  const char* text = "param n = 3;\nlsystem s { derive n; axiom F; }";
  CHECK(codes_of(text) == "");
  CheckOptions o;
  o.defines = {{"n", -2}};
  CHECK(codes(check_text(text, o)) == "E0301@2:20");
}

TEST_CASE("check: pieces", "[check]") {
  const char* ok = R"(pieces almond {
  rim hexagon(radius: 1);
  piece I = tube(length: 4, taper: 0.85);
  piece Y = fork(angle: 32, taper: 0.8);
  piece P = mesh("pieces/psi.glb");
  root I;
  I.top -> I 0.7 | Y 0.3;
  Y.left -> I;  Y.right -> I 0.5 | P 0.5;
  P.whatever -> I;
  twist any;  depth 10;
})";
  CHECK(codes_of(ok) == "");
  CHECK(codes_of("pieces p { piece I = tube(); root I; I.left -> I; }") == "E0108@1:40");
  CHECK(codes_of("pieces p { piece I = tube(); root I; I.top -> J; }") == "E0107@1:47");
  CHECK(codes_of("pieces p { piece I = tub(); root I; }") == "E0401@1:22");
  CHECK(codes_of("pieces p { piece I = mesh(); root I; }") == "E0402@1:22");
  CHECK(codes_of("pieces p { piece I = tube(); root I; spin 3; }") == "E0403@1:38");
  CHECK(codes_of("pieces p { piece I = tube(); root I; depth -1; }") == "E0404@1:44");
  CHECK(codes_of("pieces p { piece I = tube(); root I; I.top -> I 0; }") == "E0405@1:49");
  CHECK(codes_of("pieces p { piece I = tube(); }") == "E0406@1:8");
}

TEST_CASE("check: voxels", "[check]") {
  CHECK(
      codes_of("voxels v { levels 6; classes 16; axiom \"a.rvx\"; 7 -> [0 3 0 7 0 5 0 7] x3; }") ==
      "");
  CHECK(codes_of("voxels v { classes 16; 7 -> [0 3 0 7 0 5 0]; }") == "E0501@1:24");
  CHECK(codes_of("voxels v { classes 8; 7 -> [0 3 0 7 0 5 0 8]; }") == "E0502@1:43");
  CHECK(codes_of("voxels v { classes 8; 1.5 -> [0 3 0 7 0 5 0 7]; }") == "E0502@1:23");
  CHECK(codes_of("voxels v { size 8; }") == "E0503@1:12");
  CHECK(codes_of("voxels v { levels 0; }") == "E0504@1:19");
  CHECK(codes_of("voxels v { 1 -> [0 0 0 0 0 0 0 0] x0; }") == "E0505@1:36");
}

TEST_CASE("check: unused constants and productions are warned about", "[check]") {
  CHECK(codes_of("const a = 1, b = a;\nparam p = 1;\nlsystem s { axiom F; }") == "W0001@1:14");
  // A file without blocks is a library: its constants are for its importers.
  CHECK(codes_of("const a = 1, b = a;") == "");
  CHECK(codes_of("lsystem s { axiom A; A -> B; B -> A; C -> A; }") == "W0002@1:38");
  // Reached through a successor of a reached production, and through split names.
  CHECK(codes_of("lsystem s { axiom A; A -> BC; C -> D; D -> A; }") == "");
}

TEST_CASE("check: a production behind an unconditional one is shadowed", "[check]") {
  CHECK(codes_of("lsystem s { axiom A(1); A(x) -> B; A(y) -> C; }") == "W0003@1:36");
  // A guard, a different context or a different kind: no warning.
  CHECK(codes_of("lsystem s { axiom A(1); A(x) : x > 1 -> B; A(y) -> C; }") == "");
  CHECK(codes_of("lsystem s { axiom B A(1); A(x) -> B; B < A(y) -> C; }") == "");
  CHECK(codes_of("lsystem s { axiom A(1); A(x) -> B; interpret A(y) -> C; }") == "");
  // Under `select nearest` the first matching rule does not win.
  CHECK(codes_of("lsystem s { select nearest(x); axiom A(1); A(x) -> B; A(y) -> C; }") == "");
}

TEST_CASE("check: imported files share their constants and modules", "[check]") {
  // Covered end to end by the golden tests of imports; here only the -D lookup.
  SourceManager sm;
  DiagnosticSink sink;
  Program p = load_program_text("t.ramus", "param n = 1; const c = 2;", sm, sink);
  CHECK(find_define_target(p, "n") == DefineTarget::Param);
  CHECK(find_define_target(p, "c") == DefineTarget::Const);
  CHECK(find_define_target(p, "z") == DefineTarget::Unknown);
}

TEST_CASE("check: 10000 productions parse and check in well under a second", "[check][perf]") {
  std::string text = "module ";
  const int n = 10000;
  for (int i = 0; i < n; ++i) text += (i ? ", M" : "M") + std::to_string(i) + "(x)";
  text += ";\nlsystem big {\n  derive 3;\n  axiom M0(1);\n";
  for (int i = 0; i < n; ++i) {
    text += "  M" + std::to_string(i) + "(x) : x > 0 -> F(x) [ +(30) M" +
            std::to_string((i + 1) % n) + "(x * 0.9) ] M" + std::to_string((i * 7 + 3) % n) +
            "(x - 1);\n";
  }
  text += "}\n";
  // CPU time of this thread: other processes on a busy machine do not count.
  auto cpu = [] {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
  };
  double t0 = cpu();
  SourceManager sm;
  DiagnosticSink sink;
  Program p = load_program_text("big.ramus", text, sm, sink);
  double t1 = cpu();
  check_program(p, sm, sink);
  double t2 = cpu();
  INFO("parse " << t1 - t0 << " s, check " << t2 - t1 << " s (CPU)");
  CHECK(sink.all().empty());
  // The checks are linear (hash maps): about 0.15 s of CPU here.
  CHECK(t2 - t1 < 0.5);
  CHECK(t2 - t0 < 1.0);
}
