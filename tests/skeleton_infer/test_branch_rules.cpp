// Per-node rule extraction (Eq. 4.11) on hand-made skeletons with known angles and ratios, and
// against the turtle: a grammar that turns by known angles gives those angles back.
#include <catch2/catch.hpp>

#include "core/rng.h"
#include "infer/skeleton/branch_rules.h"
#include "skeleton_fixtures.h"

using namespace ramus;
using namespace ramus::skeleton_infer;
using skeleton_test::add_node;

namespace {

const ChildRule* find_child(const BranchRules& r, std::uint32_t parent_internode,
                            bool continuation) {
  const NodeRule& rule = r.rules[parent_internode];
  for (const ChildRule* c = r.begin(rule); c != r.end(rule); ++c) {
    if (r.internodes[c->internode].continuation == continuation) return c;
  }
  return nullptr;
}

}  // namespace

TEST_CASE("extraction: azimuth conventions of a vertical and a horizontal parent",
          "[skeleton_infer]") {
  double theta = 0, phi = 0;
  const double s = std::sqrt(0.5);
  // Vertical parent: the turtle's initial frame, L = (-1, 0, 0), U = (0, -1, 0).
  angle_and_azimuth({0, 0, 1}, {s, 0, s}, theta, phi);
  CHECK(theta == Approx(45));
  CHECK(phi == Approx(90));
  angle_and_azimuth({0, 0, 1}, {0, -s, s}, theta, phi);
  CHECK(phi == Approx(180));
  angle_and_azimuth({0, 0, 1}, {0, s, s}, theta, phi);
  CHECK(phi == Approx(0).margin(1e-9));
  // Horizontal parent along +x: L = (0, 1, 0), U = (0, 0, 1); phi 0 bends down, 180 up.
  angle_and_azimuth({1, 0, 0}, {s, 0, -s}, theta, phi);
  CHECK(theta == Approx(45));
  CHECK(phi == Approx(0).margin(1e-9));
  angle_and_azimuth({1, 0, 0}, {s, 0, s}, theta, phi);
  CHECK(phi == Approx(180));
  angle_and_azimuth({1, 0, 0}, {s, -s, 0}, theta, phi);
  CHECK(phi == Approx(90));
  // Straight on: theta 0, azimuth defined as 0.
  angle_and_azimuth({1, 0, 0}, {1, 0, 0}, theta, phi);
  CHECK(theta == Approx(0).margin(1e-9));
  CHECK(phi == 0);
}

TEST_CASE("extraction: a fork with known angles and ratios", "[skeleton_infer]") {
  Skeleton s;
  const auto root = add_node(s, {0, 0, 0}, kNoParent, 0.2);
  // The trunk is a chain of two segments (one internode of length 2, radius 0.2 at its base).
  const auto a = add_node(s, {0, 0, 1}, root, 0.2);
  const auto fork = add_node(s, {0, 0, 2}, a, 0.18);
  const double d = std::sqrt(0.5);
  // Continuation: straight up, length 1.5, radius 0.15. Lateral: 45 degrees towards +x,
  // length 1, radius 0.05.
  add_node(s, {0, 0, 3.5}, fork, 0.15);
  add_node(s, {d, 0, 2 + d}, fork, 0.05);
  const BranchRules r = extract_branch_rules(s);
  REQUIRE(r.internodes.size() == 3);
  const Internode& trunk = r.internodes[0];
  CHECK(trunk.length == Approx(2));
  CHECK(trunk.radius == Approx(0.2));
  CHECK(trunk.end == fork);
  REQUIRE(r.rules[0].child_count == 2);
  const ChildRule* cont = find_child(r, 0, true);
  const ChildRule* lat = find_child(r, 0, false);
  REQUIRE(cont != nullptr);
  REQUIRE(lat != nullptr);
  // Continuation first in the rule.
  CHECK(r.begin(r.rules[0]) == cont);
  CHECK(cont->theta == Approx(0).margin(1e-9));
  CHECK(cont->a == Approx(0.75));
  CHECK(cont->b == Approx(0.75));
  CHECK(lat->theta == Approx(45));
  CHECK(lat->phi == Approx(90));
  CHECK(lat->a == Approx(0.5));
  CHECK(lat->b == Approx(0.25));
  CHECK(r.internodes[cont->internode].order == 0);
  CHECK(r.internodes[cont->internode].axis_index == 1);
  CHECK(r.internodes[lat->internode].order == 1);
  CHECK(r.internodes[lat->internode].axis_index == 0);
  CHECK(r.internodes[lat->internode].depth == 1);
  // Tips have rules without children.
  CHECK(r.rules[cont->internode].child_count == 0);
  CHECK(r.tree_length.size() == 1);
  CHECK(r.tree_length[0] == Approx(4.5));
}

TEST_CASE("extraction: recovers the turtle's angles from a grown grammar", "[skeleton_infer]") {
  // The trunk is tilted so that `$` defines the frame; each child turns by `$/(phi)&(theta)`.
  const std::string text =
      "lsystem t {\n  axiom &(30)!(0.2)F(1)[$/(70)&(40)!(0.1)F(0.5)][$/(300)&(65)!(0.06)F(0.3)]"
      "$/(200)&(10)!(0.16)F(0.8);\n}\n";
  const Skeleton s = skeleton_test::grow_text("turtle_angles.ramus", text, 1);
  const BranchRules r = extract_branch_rules(s);
  REQUIRE(r.internodes.size() == 4);
  REQUIRE(r.rules[0].child_count == 3);
  const ChildRule* c = r.begin(r.rules[0]);
  // Continuation, then laterals by azimuth (70, 300).
  CHECK(c[0].theta == Approx(10));
  CHECK(c[0].phi == Approx(200));
  CHECK(c[0].a == Approx(0.8));
  CHECK(c[0].b == Approx(0.8));
  CHECK(c[1].theta == Approx(40));
  CHECK(c[1].phi == Approx(70));
  CHECK(c[1].a == Approx(0.5));
  CHECK(c[1].b == Approx(0.5));
  CHECK(c[2].theta == Approx(65));
  CHECK(c[2].phi == Approx(300));
  CHECK(c[2].a == Approx(0.3));
  CHECK(c[2].b == Approx(0.3));
}

TEST_CASE("extraction: property over random trees: counts, lengths, ranges", "[skeleton_infer]") {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    Rng rng(seed);
    Skeleton s;
    add_node(s, {0, 0, 0}, kNoParent, 0.3);
    const int n = 2 + int(rng.below(300));
    for (int i = 1; i < n; ++i) {
      const auto parent = std::uint32_t(rng.below(std::uint64_t(i)));
      const Vec3 p = s.nodes[parent].position +
                     Vec3{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(0.1, 1)};
      add_node(s, p, parent, rng.uniform(0.01, 0.3));
    }
    const BranchRules r = extract_branch_rules(s);
    // Internode lengths add up to the skeleton's length.
    double total = 0;
    for (const Internode& in : r.internodes) total += in.length;
    CHECK(total == Approx(s.total_length()));
    // Every internode but the first of the tree is the child of exactly one rule.
    std::size_t children = 0;
    for (const NodeRule& rule : r.rules) {
      CHECK(rule.child_count != 1);
      children += rule.child_count;
      const ChildRule* c = r.begin(rule);
      for (std::uint32_t k = 0; k < rule.child_count; ++k) {
        CHECK(c[k].theta >= 0);
        CHECK(c[k].theta <= 180);
        CHECK(c[k].phi >= 0);
        CHECK(c[k].phi < 360);
        // Exactly one continuation per branch node, stored first.
        CHECK(r.internodes[c[k].internode].continuation == (k == 0));
        if (k > 0) CHECK(c[k].theta >= c[0].theta);
      }
    }
    std::size_t starts = 0;
    for (const Internode& in : r.internodes) starts += in.parent == kNone ? 1 : 0;
    CHECK(children + starts == r.internodes.size());
  }
}

TEST_CASE("extraction: degenerate skeletons", "[skeleton_infer]") {
  Skeleton empty;
  CHECK(extract_branch_rules(empty).internodes.empty());
  Skeleton one;
  add_node(one, {0, 0, 0}, kNoParent);
  CHECK(extract_branch_rules(one).internodes.empty());
  // A chain without branching: one internode whose rule has no children.
  Skeleton chain;
  auto p = add_node(chain, {0, 0, 0}, kNoParent);
  for (int k = 1; k <= 10; ++k) p = add_node(chain, {0.1 * k, 0, double(k)}, p);
  const BranchRules r = extract_branch_rules(chain);
  REQUIRE(r.internodes.size() == 1);
  CHECK(r.rules[0].child_count == 0);
  CHECK(r.internodes[0].length == Approx(chain.total_length()));
  // Coincident nodes: no NaN, the direction falls back to the parent's.
  Skeleton flat;
  const auto a = add_node(flat, {0, 0, 0}, kNoParent);
  const auto b = add_node(flat, {0, 0, 1}, a);
  add_node(flat, {0, 0, 1}, b);
  add_node(flat, {1, 0, 1}, b);
  const BranchRules f = extract_branch_rules(flat);
  for (const ChildRule& c : f.children) {
    CHECK(std::isfinite(c.theta));
    CHECK(std::isfinite(c.phi));
    CHECK(std::isfinite(c.a));
  }
  // A cycle is an ExtractError, not a hang.
  Skeleton cyc;
  add_node(cyc, {0, 0, 0}, 1);
  add_node(cyc, {0, 0, 1}, 0);
  CHECK_THROWS_AS(extract_branch_rules(cyc), ExtractError);
}
