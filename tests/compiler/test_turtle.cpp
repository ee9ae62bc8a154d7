// The 3D turtle: ABOP conventions (ch. 1.5), the frame, branches, widths, organs, tropism
// (ch. 2.2), interpretation rules and their depth, and the 3D Hilbert curve of ABOP fig. 1.11.
#include <catch2/catch.hpp>
#include <cmath>
#include <set>
#include <tuple>

#include "engine_helpers.h"

using namespace ramus;
using ramus::test::skeleton_of;

namespace {
bool near(const Vec3& a, const Vec3& b, double eps = 1e-9) { return distance(a, b) < eps; }
}  // namespace

TEST_CASE("turtle: F draws up, + turns counter-clockwise in the front view", "[turtle]") {
  Skeleton sk = skeleton_of("lsystem t { axiom F + F - F; }", 0);
  REQUIRE(sk.size() == 4);
  CHECK(sk.nodes[0].parent == kNoParent);
  CHECK(near(sk.nodes[1].position, {0, 0, 1}));
  CHECK(near(sk.nodes[2].position, {-1, 0, 1}));  // left, seen from -y
  CHECK(near(sk.nodes[3].position, {-1, 0, 2}));
  CHECK(sk.nodes[3].parent == 2);
  CHECK(sk.validate().empty());
}

TEST_CASE("turtle: pitch, roll and turn around keep a right-handed frame", "[turtle]") {
  Skeleton sk = skeleton_of("lsystem t { axiom & F ^ F & \\ + F / / + F | F $ F; }", 0);
  for (const auto& n : sk.nodes) {
    CHECK(near(cross(n.heading, n.left), n.up));
    CHECK(std::abs(length(n.heading) - 1) < 1e-12);
  }
  // & pitches the heading down towards -U = +y, ^ up towards U = -y.
  CHECK(near(sk.nodes[1].position, {0, 1, 0}));
  CHECK(near(sk.nodes[2].position, {0, 1, 1}));
}

TEST_CASE("turtle: roll rotates L and U about H", "[turtle]") {
  // After \(90) the left vector is what U was before (-y); + then turns towards it.
  Skeleton sk = skeleton_of("lsystem t { axiom \\(90) + F; }", 0);
  CHECK(near(sk.nodes[1].position, {0, -1, 0}));
  Skeleton sk2 = skeleton_of("lsystem t { axiom /(90) + F; }", 0);
  CHECK(near(sk2.nodes[1].position, {0, 1, 0}));
}

TEST_CASE("turtle: branches, order, widths, f and organs", "[turtle]") {
  Skeleton sk = skeleton_of(
      "lsystem t { width 2; width_decay 0.5; axiom F [ ! + F ~(3) ] F f F !(4) F; }", 0);
  REQUIRE(sk.size() == 7);
  CHECK(sk.nodes[1].radius == 1);
  CHECK(sk.nodes[2].parent == 1);  // branch starts at the first segment's end
  CHECK(sk.nodes[2].order == 1);
  CHECK(sk.nodes[2].radius == 0.5);
  CHECK(sk.nodes[3].parent == 1);  // after ]: back on the trunk
  CHECK(sk.nodes[3].order == 0);
  CHECK(sk.nodes[4].parent == kNoParent);  // f: a new, disconnected segment
  CHECK(near(sk.nodes[4].position, {0, 0, 3}));
  CHECK(sk.nodes[5].parent == 4);
  CHECK(sk.nodes[6].radius == 2);
  REQUIRE(sk.organs.size() == 1);
  CHECK(sk.organs[0].node == 2);
  CHECK(sk.organs[0].size == 3);
  CHECK(sk.roots().size() == 2);
  CHECK(sk.validate().empty());
}

TEST_CASE("turtle: step and angle settings and explicit arguments", "[turtle]") {
  Skeleton sk = skeleton_of("lsystem t { step 2; angle 45; axiom F +(90) F(3) -; }", 0);
  CHECK(near(sk.nodes[1].position, {0, 0, 2}));
  CHECK(near(sk.nodes[2].position, {-3, 0, 2}));
}

TEST_CASE("turtle: source modules index the derived string", "[turtle]") {
  Skeleton sk = skeleton_of("lsystem t { axiom A B; A -> F; B -> + F F; }", 1);
  REQUIRE(sk.size() == 4);
  CHECK(sk.nodes[1].source_module == 0);
  CHECK(sk.nodes[2].source_module == 2);
  CHECK(sk.nodes[3].source_module == 3);
}

TEST_CASE("turtle: interpretation rules apply only to the turtle, up to max_depth", "[turtle]") {
  const std::string src = "lsystem t { max_depth 3; axiom A; interpret A -> F A; }";
  ir::Grammar g = ramus::test::grammar_of(src);
  ModuleString s = ramus::test::derive_of(g, 2);
  CHECK(to_text(g, s) == "A");  // the derived string is untouched
  Skeleton sk = interpret(g, s, TurtleOptions{});
  CHECK(sk.size() == 4);  // three levels: F F F A, plus the root node
  for (const auto& n : sk.nodes) CHECK(n.source_module == 0);
  Skeleton sk2 = skeleton_of("lsystem t { axiom A(2); interpret A(x) -> F(x) [ + F(x / 2) ]; }", 0);
  REQUIRE(sk2.size() == 3);
  CHECK(near(sk2.nodes[2].position, {-1, 0, 2}));
}

TEST_CASE("turtle: the cut skips the rest of the branch", "[turtle][cut]") {
  Skeleton sk = skeleton_of("lsystem t { axiom F [ + F X ] F; interpret X -> % F; }", 0);
  CHECK(sk.size() == 4);
}

TEST_CASE("turtle: tropism bends the heading towards T (ABOP ch. 2.2)", "[turtle]") {
  Skeleton sk =
      skeleton_of("lsystem t { tropism 0, 0, -1; elasticity 0.2; axiom +(90) F F F; }", 0);
  // Heading starts horizontal (-x); each segment bends it down by e |H x T|.
  REQUIRE(sk.size() == 4);
  CHECK(sk.nodes[2].position.z < -0.1);
  const double a1 = 0.2;  // |H x T| = 1 for a horizontal heading
  CHECK(std::abs(sk.nodes[2].position.z - sk.nodes[1].position.z + std::sin(a1)) < 1e-9);
  Skeleton none = skeleton_of("lsystem t { tropism 0, 0, -1; axiom +(90) F F; }", 0);
  CHECK(std::abs(none.nodes[2].position.z) < 1e-12);
}

// ABOP fig. 1.11 (p. 20): the 3D Hilbert curve. Its turtle path visits 8^n distinct lattice
// points inside a (2^n - 1)^3 box; an axis or sign error in & ^ \ / | breaks that.
TEST_CASE("turtle: the 3D Hilbert curve visits every lattice point of its box once",
          "[turtle][abop]") {
  const std::string src = R"(
    lsystem hilbert { angle 90; axiom A;
      A -> B - F + C F C + F - D & F ^ D - F + & & C F C + F + B / / ;
      B -> A & F ^ C F B ^ F ^ D ^ ^ - F - D ^ | F ^ B | F C ^ F ^ A / / ;
      C -> | D ^ | F ^ B - F + C ^ F ^ A & & F A & F ^ C + F + B ^ F ^ D / / ;
      D -> | C F B - F + B | F A & F ^ A & & F B - F + B | F C / / ;
    })";
  for (int n = 1; n <= 3; ++n) {
    Skeleton sk = skeleton_of(src, n);
    const int side = (1 << n) - 1;
    std::set<std::tuple<long, long, long>> points;
    Vec3 lo, hi;
    sk.bounds(lo, hi);
    for (const auto& node : sk.nodes) {
      const Vec3 p = node.position;
      CHECK(near(p, {std::round(p.x), std::round(p.y), std::round(p.z)}, 1e-6));
      points.insert({std::lround(p.x), std::lround(p.y), std::lround(p.z)});
    }
    INFO("n = " << n);
    CHECK(points.size() == std::size_t(1) << (3 * n));
    CHECK(sk.size() == std::size_t(1) << (3 * n));  // one path: root + 8^n - 1 segments
    CHECK(std::lround(hi.x - lo.x) == side);
    CHECK(std::lround(hi.y - lo.y) == side);
    CHECK(std::lround(hi.z - lo.z) == side);
  }
}
