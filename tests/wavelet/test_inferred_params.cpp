// An inferred wavelet grammar reads as a grammar: a `param` block of named quantities that the
// text uses by name, a comment before each production saying what it grows, no expression
// nesting more than two function calls; and `-D` of a param changes the regrown tree the way its
// comment says (cell scales the tree, branch_tilt tilts the laterals).
#include <catch2/catch.hpp>
#include <cctype>
#include <sstream>

#include "fractal_cloud.h"
#include "infer/wavelet/infer_grammar.h"
#include "regrown_tree_util.h"

using namespace ramus;
using namespace ramus::wavelet;
using namespace ramus::wavelet::test;

namespace {

std::string inferred(std::uint64_t seed) {
  WaveletInferOptions o;
  o.seed = seed;
  return infer_wavelet_grammar(fractal_tree_cloud(seed), o).ramus_text;
}

// The deepest nesting of function calls (a name followed by `(`) in one line.
int call_depth(const std::string& line) {
  std::vector<bool> call;  // per open parenthesis: opened by a call
  int depth = 0, most = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '/' && i + 1 < line.size() && line[i + 1] == '/') break;  // a comment
    if (line[i] == '(') {
      const bool named =
          i > 0 && (std::isalnum(static_cast<unsigned char>(line[i - 1])) || line[i - 1] == '_');
      call.push_back(named);
      if (named) most = std::max(most, ++depth);
    } else if (line[i] == ')' && !call.empty()) {
      if (call.back()) --depth;
      call.pop_back();
    }
  }
  return most;
}

// Mean |z| of the segment directions: 1 for a pole, 0 for a flat tree.
double mean_uprightness(const Skeleton& s) {
  double sum = 0, total = 0;
  for (const SkeletonNode& n : s.nodes) {
    if (n.parent == kNoParent) continue;
    const Vec3 d = n.position - s.nodes[n.parent].position;
    const double len = std::sqrt(dot(d, d));
    sum += std::abs(d.z);
    total += len;
  }
  return total > 0 ? sum / total : 0;
}

double param_value(const std::string& text, const std::string& name) {
  const std::size_t at = text.find("param " + name + " = ");
  REQUIRE(at != std::string::npos);
  return std::stod(text.substr(at + name.size() + 9));
}

}  // namespace

TEST_CASE("inferred wavelet grammar: params, a comment per production, shallow expressions",
          "[wavelet][params]") {
  for (std::uint64_t seed : {1, 2, 3}) {
    INFO("seed " << seed);
    const std::string text = inferred(seed);
    CHECK(text.find("param cell = ") != std::string::npos);
    CHECK(text.find("param branch_tilt = ") != std::string::npos);
    CHECK(text.find("param width_ratio = ") != std::string::npos);
    // The params come before the blocks that use them, and the text uses each by name.
    CHECK(text.find("param cell") < text.find("lsystem "));
    CHECK(text.find("* cell") != std::string::npos);
    CHECK(text.find("* branch_tilt") != std::string::npos);
    CHECK(text.find("* width_ratio") != std::string::npos);
    std::istringstream in(text);
    std::string line, previous;
    int productions = 0;
    while (std::getline(in, line)) {
      INFO(line);
      CHECK(call_depth(line) <= 2);
      if (line.rfind("  V(a, e, l, s, w) @", 0) == 0) {
        ++productions;
        CHECK(previous.rfind("  // Grows a ", 0) == 0);
      }
      previous = line;
    }
    CHECK(productions > 0);
  }
}

TEST_CASE("inferred wavelet grammar: -D of a param changes the regrown tree as its comment says",
          "[wavelet][params]") {
  const std::string text = inferred(4);
  const Skeleton base = grow_text(text);
  const TreeShape t = shape_of(base);
  // cell: every length of the axiom is a multiple of it and successors are relative, so the
  // whole tree scales with it.
  const double cell = param_value(text, "cell");
  const TreeShape doubled = shape_of(grow_text(text, {{"cell", 2 * cell}}));
  CHECK(doubled.height == Approx(2 * t.height).epsilon(1e-9));
  CHECK(doubled.length == Approx(2 * t.length).epsilon(1e-9));
  // branch_tilt: the laterals' angle from the vertical; smaller tilts them up.
  const double tilt = param_value(text, "branch_tilt");
  const double upright = mean_uprightness(base);
  CHECK(mean_uprightness(grow_text(text, {{"branch_tilt", tilt / 3}})) > upright);
  CHECK(mean_uprightness(grow_text(text, {{"branch_tilt", 90}})) < upright);
  // width_ratio: laterals' widths are multiples of it.
  const double ratio = param_value(text, "width_ratio");
  const Skeleton thin = grow_text(text, {{"width_ratio", ratio / 2}});
  double before = 0, after = 0;
  for (const SkeletonNode& n : base.nodes) before += n.radius;
  for (const SkeletonNode& n : thin.nodes) after += n.radius;
  CHECK(after < before);
  // The structure does not change: same number of nodes.
  CHECK(thin.nodes.size() == base.nodes.size());
}
