#include "lsp/language_words.h"

namespace ramus::lsp {

namespace {

// docs/language.md, "Turtle" (the rotations are ABOP ch. 1.5's, the tropism ch. 2.2's).
constexpr Word kTurtle[] = {
    {"F", "F(l)",
     "move forward `l` (default `step`) drawing a segment: a skeleton node at the end point"},
    {"f", "f(l)",
     "move forward `l` without drawing; the next `F` starts a new, disconnected segment"},
    {"+", "+(a)", "turn left about U by `a` degrees (default `angle`): H moves towards L"},
    {"-", "-(a)", "turn right about U by `a` degrees (default `angle`)"},
    {"&", "&(a)", "pitch down about L by `a` degrees (default `angle`): H moves towards -U"},
    {"^", "^(a)", "pitch up about L by `a` degrees (default `angle`)"},
    {"\\", "\\(a)", "roll left about H by `a` degrees (default `angle`): L moves towards U"},
    {"/", "/(a)", "roll right about H by `a` degrees (default `angle`)"},
    {"|", "|", "turn around: 180 degrees about U"},
    {"$", "$", "roll about H so that L is horizontal (ABOP ch. 2)"},
    {"[", "[", "push the turtle's whole state; the branch order grows by 1"},
    {"]", "]", "pop the state pushed by the matching `[`"},
    {"!", "!(w)", "set the width to `w`; a bare `!` multiplies it by `width_decay`"},
    {"'", "'(c)", "set the colour index to `c`; a bare `'` increments it"},
    {"~", "~(s, k)",
     "an organ anchor (leaf) of size `s` (default 1) and kind `k` (default 0, leaf) at the current "
     "point and frame"},
    {"%", "%", "cut: skip the rest of the current branch"},
    // ABOP ch. 5.1 polygons (issue 20, point 1).
    {"{", "{", "start a polygon (ABOP 5.1)"},
    {"}", "}", "close the polygon started by the matching `{`"},
    {".", ".", "record the turtle's position as a vertex of the current polygon"},
};

// grammar/builtins.h; trigonometry in degrees.
constexpr Word kBuiltins[] = {
    {"sin", "sin(x)", "sine of `x` degrees"},
    {"cos", "cos(x)", "cosine of `x` degrees"},
    {"tan", "tan(x)", "tangent of `x` degrees"},
    {"asin", "asin(x)", "arc sine in degrees, `x` in [-1, 1]"},
    {"acos", "acos(x)", "arc cosine in degrees, `x` in [-1, 1]"},
    {"atan", "atan(x)", "arc tangent in degrees"},
    {"atan2", "atan2(y, x)", "the angle of the point (x, y) in degrees"},
    {"sqrt", "sqrt(x)", "square root, `x` >= 0"},
    {"exp", "exp(x)", "e to the power `x`"},
    {"log", "log(x)", "natural logarithm, `x` > 0"},
    {"log10", "log10(x)", "decimal logarithm, `x` > 0"},
    {"pow", "pow(x, y)", "`x` to the power `y` (also written `x ^ y`)"},
    {"abs", "abs(x)", "absolute value"},
    {"floor", "floor(x)", "the largest integer <= `x`"},
    {"ceil", "ceil(x)", "the smallest integer >= `x`"},
    {"round", "round(x)", "`x` rounded to the nearest integer, halves away from zero"},
    {"min", "min(a, b)", "the smaller of `a` and `b`"},
    {"max", "max(a, b)", "the larger of `a` and `b`"},
    {"clamp", "clamp(x, lo, hi)", "`x` limited to [`lo`, `hi`]"},
    {"sign", "sign(x)", "-1, 0 or 1 by the sign of `x`"},
    {"uniform", "uniform(a, b)",
     "a uniform random number in [a, b) from the grammar's seeded stream (not in `const`)"},
    {"normal", "normal(m, s)",
     "a normal random number of mean `m` and deviation `s` from the grammar's seeded stream (not "
     "in `const`)"},
};

// docs/language.md, "Settings".
constexpr Word kSettings[] = {
    {"derive", "derive N;", "derivation steps (default 0; `-n` overrides)"},
    {"seed", "seed S;",
     "the seed of the stochastic choices and random functions (default 0; `--seed` overrides)"},
    {"angle", "angle A;", "default turn angle in degrees (default 90)"},
    {"step", "step L;", "default length of `F` and `f` (default 1)"},
    {"width", "width W;", "initial width (default 1)"},
    {"width_decay", "width_decay k;", "the factor of a bare `!` (default 0.707)"},
    {"tropism", "tropism x, y, z;", "the tropism vector T (default 0, 0, -1; ABOP ch. 2.2)"},
    {"elasticity", "elasticity e;", "how strongly segments bend towards T (default 0: no tropism)"},
    {"max_depth", "max_depth D;",
     "the depth limit of interpretation and decomposition (1..255, default 8)"},
};

// docs/language.md, "Keywords".
constexpr Word kKeywords[] = {
    {"import", "import \"file.ramus\"; | import a.b;", "read another file, or stdlib/a/b.ramus"},
    {"const", "const name = expr, ...;", "constants, folded when the grammar is compiled"},
    {"param", "param name = expr, ...;", "parameters: constants that `-D name=value` may override"},
    {"module", "module A(l, w), B;",
     "declare modules: names of several letters that are one module, with their arity"},
    {"lsystem", "lsystem name { ... }", "a parametric L-system: settings, axiom, productions"},
    {"pieces", "pieces name { ... }", "piece-match rules: rims, pieces and attach rules"},
    {"voxels", "voxels name { ... }", "voxel rules: a class and its eight children"},
    {"axiom", "axiom modules;", "the string derivation starts from"},
    {"ignore", "ignore symbols;", "symbols context matching does not see"},
    {"consider", "consider symbols;", "the only symbols context matching sees"},
    {"select", "select nearest(keys);", "nearest-rule selection in rule space"},
    {"interpret", "interpret A -> ...;",
     "a production applied for the turtle only, never changing the derived string"},
    {"decompose", "decompose A -> ...;",
     "a production applied after each step until nothing changes"},
    {"rim", "rim name(args);", "a rim shape of a pieces block"},
    {"piece", "piece name = kind(args);",
     "a piece: tube, fork, trifurcation, attachment or mesh(\"file\")"},
    {"true", "true", "the boolean true (1 in arithmetic)"},
    {"false", "false", "the boolean false (0 in arithmetic)"},
};

}  // namespace

std::span<const Word> turtle_symbols() { return kTurtle; }
std::span<const Word> builtin_functions() { return kBuiltins; }
std::span<const Word> lsystem_settings() { return kSettings; }
std::span<const Word> keywords() { return kKeywords; }

const Word* find_word(std::span<const Word> words, std::string_view name) {
  for (const Word& w : words) {
    if (w.name == name) return &w;
  }
  return nullptr;
}

}  // namespace ramus::lsp
