// Scaffold grammars (infer/skeleton/scaffold_grammar.h): the grammar inferred from a tree regrows
// that tree -- its envelope, one connected piece, plausible radii and internodes, its lean --
// for the bundled example trees and every bundled scan; it reads as species-level params used
// by name; -D of a param changes the tree as its name says; a scan with no tree in it is refused.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "../cli/cli_runner.h"
#include "formats/point_cloud_io.h"
#include "formats/skeleton_json.h"
#include "infer/shape/envelope.h"
#include "infer/shape/tree_shape.h"
#include "infer/skeleton/scaffold_grammar.h"
#include "skeleton_fixtures.h"

using namespace ramus;
using cli_test::run_ramus;
using cli_test::slurp;

namespace {

std::string data(const std::string& name) {
  return std::string(RAMUS_SHARED_DIR) + "/data/" + name;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// How far a tree reaches below its root (0 unless twigs hang below the trunk's foot, as the
// weeping tree's whips do). A grown tree stands at the origin, its input where it was scanned.
double depth_below_root(const Skeleton& s) {
  double root = 1e300, low = 1e300;
  for (std::uint32_t r : s.roots()) root = std::min(root, s.nodes[r].position.z);
  for (const SkeletonNode& n : s.nodes) low = std::min(low, n.position.z);
  return root - low;
}

// The plausibility of a grown tree against the tree it was inferred from (height `height`,
// reaching `below` under its root, trunk lean `lean`): one piece from one root, nothing below
// the base (within the axiom's drawing tolerance), no child wider than 1.05 x its parent, no
// internode over height / 3, the lean within 10 degrees.
void check_plausible(const Skeleton& grown, double height, double below, double lean,
                     const std::string& what) {
  INFO(what);
  REQUIRE(grown.validate().empty());
  CHECK(grown.roots().size() == 1);
  const shape::TreeShape shape = shape::measure_tree_shape(grown);
  const double base_z = grown.nodes[grown.roots().front()].position.z - below;
  CHECK(shape.pieces == 1);
  CHECK(shape.largest_piece_share == Approx(1.0));
  std::size_t under = 0, wider = 0, longer = 0;
  double lowest = base_z;
  for (const SkeletonNode& n : grown.nodes) {
    lowest = std::min(lowest, n.position.z);
    // The axiom keeps the scaffold's bends to within 1 % of the height (Douglas-Peucker), so a
    // drawn limb may pass that much below a measured one (the weeping tree's lowest whip tip:
    // 0.26 %).
    if (n.position.z < base_z - 0.01 * height) ++under;
    if (n.parent == kNoParent) continue;
    const SkeletonNode& p = grown.nodes[n.parent];
    if (n.radius > 1.05 * p.radius + 1e-12) ++wider;
    if (length(n.position - p.position) > height / 3) ++longer;
  }
  INFO("lowest node " << (base_z - lowest) / height << " of the height below the base");
  CHECK(under == 0);
  CHECK(wider == 0);
  CHECK(longer == 0);
  REQUIRE(std::isfinite(shape.lean_degrees));
  INFO("lean " << shape.lean_degrees << " against " << lean);
  CHECK(std::abs(shape.lean_degrees - lean) <= 10.0);
}

double crown_radius(const Skeleton& s) {
  const Vec3 root = s.nodes[s.roots().front()].position;
  std::vector<double> r;
  for (const SkeletonNode& n : s.nodes)
    r.push_back(std::hypot(n.position.x - root.x, n.position.y - root.y));
  std::sort(r.begin(), r.end());
  return r[r.size() * 9 / 10];
}

// The deepest nesting of function calls in `text`: a call is a lowercase name of two or more
// letters followed by '(' (modules of inferred grammars are single letters or symbols).
int call_nesting(const std::string& text) {
  std::vector<bool> open;  // per open parenthesis: whether it is a call's
  int depth = 0, deepest = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '(') {
      std::size_t k = i;
      while (k > 0 && (std::islower(static_cast<unsigned char>(text[k - 1])) || text[k - 1] == '_'))
        --k;
      const bool call = i - k >= 2;
      open.push_back(call);
      depth += call ? 1 : 0;
      deepest = std::max(deepest, depth);
    } else if (text[i] == ')' && !open.empty()) {
      depth -= open.back() ? 1 : 0;
      open.pop_back();
    }
  }
  return deepest;
}

}  // namespace

TEST_CASE("scaffold grammar: the example trees regrow their envelope, plausibly, over seeds",
          "[skeleton_infer]") {
  for (const char* name : {"broadleaf", "conifer", "weeping"}) {
    const Skeleton input =
        skeleton_test::grow_example(std::string("examples/trees/") + name + ".ramus");
    const skeleton_infer::ScaffoldGrammar g = skeleton_infer::infer_scaffold_grammar(input);
    INFO(name);
    std::string messages;
    REQUIRE(skeleton_test::grammar_checks(g.text, messages));
    CHECK(skeleton_test::formatted(g.text) == g.text);
    const double lean = shape::lean_degrees(input);
    const double below = depth_below_root(input);
    std::vector<double> iou;
    for (int seed = 1; seed <= 10; ++seed) {
      const Skeleton grown = skeleton_test::grow_text(std::string(name) + "_scaffold.ramus", g.text,
                                                      std::uint64_t(seed));
      if (seed <= 5) iou.push_back(shape::envelope_iou(input, grown));
      check_plausible(grown, g.height, below, lean,
                      std::string(name) + " seed " + std::to_string(seed));
      // The budgets keep the input's total length, whatever the seed.
      CHECK(grown.total_length() == Approx(input.total_length()).epsilon(0.03));
    }
    // Measured: broadleaf 0.93, conifer 0.95, weeping 0.92.
    CHECK(median(iou) >= 0.7);
  }
}

TEST_CASE("scaffold grammar: every bundled scan regrows its envelope as well as its reconstruction",
          "[skeleton_infer]") {
  for (const char* scan_name : {"adtree_tree1.xyz", "adtree_ahn3_delft.xyz", "rtwig_cloud.txt",
                                "plantscan3d_A3B4.asc", "pytlidar_tree_1.las"}) {
    const std::string stem = std::filesystem::path(scan_name).stem().string();
    const std::string out = skeleton_test::scratch(stem + "_scaffold.ramus").string();
    const std::string recon = skeleton_test::scratch(stem + "_scaffold.json").string();
    const auto r = run_ramus(
        {"infer", data(scan_name), "-o", out, "--method", "skeleton", "--write-skeleton", recon});
    INFO(scan_name << "\n" << r.out);
    REQUIRE(r.status == 0);
    const PointCloud scan = read_point_cloud(data(scan_name));
    const Skeleton input = read_skeleton_json(recon);
    const double reference = shape::envelope_iou(scan, input);
    const std::string text = slurp(out);
    const double lean = shape::lean_degrees(scan);
    const double below = depth_below_root(input);
    double height = 0;
    {
      Vec3 lo, hi;
      input.bounds(lo, hi);
      height = hi.z - lo.z;
    }
    std::vector<double> iou;
    for (int seed = 1; seed <= 8; ++seed) {
      const Skeleton grown =
          skeleton_test::grow_text(stem + "_regrown.ramus", text, std::uint64_t(seed));
      if (seed <= 5) iou.push_back(shape::envelope_iou(scan, grown));
      check_plausible(grown, height, below, lean,
                      std::string(scan_name) + " seed " + std::to_string(seed));
    }
    INFO("reconstruction " << reference << ", grown median " << median(iou));
    // Measured (grown / reconstruction): 0.83/0.84, 0.53/0.53, 0.83/0.81, 0.56/0.57, 0.80/0.82;
    // with the chain cylinders of the centre lines the sparse airborne adtree_ahn3_delft's
    // reconstruction scores 0.495 (grown 0.498), hence its lower floor.
    CHECK(median(iou) >= 0.9 * reference);
    CHECK(median(iou) >= (stem == "adtree_ahn3_delft" ? 0.45 : 0.5));
  }
}

TEST_CASE("scaffold grammar: a readable file of named params", "[skeleton_infer]") {
  const Skeleton input = skeleton_test::grow_example("examples/trees/broadleaf.ramus");
  const skeleton_infer::ScaffoldGrammar g = skeleton_infer::infer_scaffold_grammar(input);
  std::istringstream lines(g.text);
  std::string line, previous;
  std::vector<std::string> params;
  std::size_t productions = 0;
  bool in_block = false, before_block = true;
  while (std::getline(lines, line)) {
    const std::size_t first = line.find_first_not_of(' ');
    const std::string trimmed = first == std::string::npos ? "" : line.substr(first);
    if (trimmed.rfind("lsystem ", 0) == 0) in_block = true, before_block = false;
    if (before_block) {
      // Only comments and params before the block.
      CHECK((trimmed.rfind("//", 0) == 0 || trimmed.rfind("param ", 0) == 0 || trimmed.empty()));
      if (trimmed.rfind("param ", 0) == 0)
        params.push_back(trimmed.substr(6, trimmed.find(' ', 6) - 6));
    }
    if (in_block && trimmed.find("->") != std::string::npos) {
      ++productions;
      INFO(line);
      CHECK(previous.find("//") != std::string::npos);  // a comment says what it grows
    }
    if (!trimmed.empty() && trimmed.rfind("|", 0) != 0) previous = trimmed;
  }
  CHECK(productions >= 1);
  CHECK(productions <= 30);
  CHECK(g.productions == productions);
  for (const char* p :
       {"branch_angle", "kink_angle", "lateral_width",
        "continuation_width", "lateral_share", "internode_length", "gravitropism"}) {
    INFO(p);
    CHECK(std::find(params.begin(), params.end(), p) != params.end());
  }
  // Every param is used by name in the block.
  const std::string block = g.text.substr(g.text.find("lsystem "));
  for (const std::string& p : params) {
    INFO(p);
    CHECK(block.find(p) != std::string::npos);
  }
  CHECK(call_nesting(g.text) <= 2);
  CHECK(call_nesting("clamp(normal(a, b), c, d)") == 2);
  CHECK(call_nesting("F(sqrt(abs(exp(x))))") == 3);
}

TEST_CASE("scaffold grammar: -D branch_angle widens the crown, -D lateral_share fills it",
          "[skeleton_infer]") {
  const Skeleton input = skeleton_test::grow_example("examples/trees/broadleaf.ramus");
  const skeleton_infer::ScaffoldGrammar g = skeleton_infer::infer_scaffold_grammar(input);
  const std::string path = skeleton_test::write_temp("broadleaf_defines.ramus", g.text);
  auto grow = [&](const std::vector<std::pair<std::string, double>>& defines, std::uint64_t seed) {
    GrowOptions o;
    o.seed = seed;
    o.defines = defines;
    SourceManager sm;
    DiagnosticSink diags;
    return grow_file(path, o, sm, diags);
  };
  double narrow = 0, wide = 0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    narrow += crown_radius(grow({{"branch_angle", 10}}, seed));
    wide += crown_radius(grow({{"branch_angle", 80}}, seed));
  }
  INFO("crown radius, branch angle 10: " << narrow / 5 << ", 80: " << wide / 5);
  CHECK(wide > 1.05 * narrow);
  // A wider gravitropism bends the shoots down: the crown's fine growth sits lower.
  auto mean_z = [](const Skeleton& s) {
    double z = 0;
    for (const SkeletonNode& n : s.nodes) z += n.position.z;
    return z / double(s.size());
  };
  double stiff = 0, bent = 0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    stiff += mean_z(grow({{"gravitropism", 0}}, seed));
    bent += mean_z(grow({{"gravitropism", 0.5}}, seed));
  }
  CHECK(bent < stiff);
}

TEST_CASE("scaffold grammar: the same input and seed write the same bytes, no segment is an error",
          "[skeleton_infer]") {
  const Skeleton input = skeleton_test::grow_example("examples/trees/weeping.ramus");
  CHECK(skeleton_infer::infer_scaffold_grammar(input).text ==
        skeleton_infer::infer_scaffold_grammar(input).text);
  Skeleton one;
  skeleton_test::add_node(one, {0, 0, 0}, kNoParent);
  CHECK_THROWS(skeleton_infer::infer_scaffold_grammar(one));
  // A tree that is all scaffold: the axiom alone, no production that never applies.
  Skeleton line;
  const std::uint32_t a = skeleton_test::add_node(line, {0, 0, 0}, kNoParent, 0.2);
  skeleton_test::add_node(line, {0, 0, 3}, a, 0.1);
  const skeleton_infer::ScaffoldGrammar g = skeleton_infer::infer_scaffold_grammar(line);
  std::string messages;
  CHECK(skeleton_test::grammar_checks(g.text, messages));
  CHECK(g.productions == 0);
  CHECK(g.text.find("->") == std::string::npos);
  const Skeleton grown = skeleton_test::grow_text("line_scaffold.ramus", g.text, 1);
  CHECK(grown.total_length() == Approx(3.0));
}

TEST_CASE("infer skeleton cli: scans with no tree in them are refused", "[skeleton_infer]") {
  auto refuse = [](const std::string& name, const std::string& points, const char* what) {
    const std::string scan = skeleton_test::write_temp(name, points);
    const std::string out = skeleton_test::scratch(name + ".ramus").string();
    std::filesystem::remove(out);
    const auto r = run_ramus({"infer", scan, "-o", out, "--method", "skeleton"});
    INFO(name << ": " << r.out);
    CHECK(r.status == 1);
    CHECK(r.out.find(what) != std::string::npos);
    CHECK(!std::filesystem::exists(out));
  };
  std::ostringstream plane, flat;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) plane << i * 0.05 << ' ' << j * 0.05 << " 0\n";
  for (int i = 0; i < 400; ++i) flat << std::sin(i) * 2 << ' ' << std::cos(i * 1.3) * 2 << " 1.5\n";
  // Measured messages: "every point lies in the terrain layer: no tree stands above the ground"
  // (plane, one height), "no dense cluster of points near the ground: no tree base found".
  refuse("plane.xyz", plane.str(), "no tree");
  refuse("flat.xyz", flat.str(), "no tree");
  refuse("few.xyz", "0 0 0\n0 0 1\n0.1 0 2\n", "no tree");
}
