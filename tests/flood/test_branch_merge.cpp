// Branch merging (Alg. 6-7) on constructed skeletons with known outcomes, plus invariants over
// random trees.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/rng.h"
#include "reconstruct/merge/branch_merge.h"

using namespace ramus;
using merge::merge_branches;
using merge::MergeOptions;

namespace {

std::uint32_t add(Skeleton& s, Vec3 p, std::uint32_t parent, double r = 0.1) {
  SkeletonNode n;
  n.position = p;
  n.parent = parent;
  n.radius = r;
  return s.add(n);
}

Vec3 in_xz(double deg, double len) {
  const double a = deg * M_PI / 180;
  return {len * std::sin(a), 0, len * std::cos(a)};
}

bool parents_first(const Skeleton& s) {
  for (std::uint32_t i = 0; i < s.size(); ++i) {
    if (s.nodes[i].parent != kNoParent && s.nodes[i].parent >= i) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("merge: a straight chain collapses to one segment", "[merge]") {
  Skeleton s;
  std::uint32_t prev = add(s, {0, 0, 0}, kNoParent);
  for (int k = 1; k <= 5; ++k) prev = add(s, {0, 0, double(k)}, prev, 0.1 * (6 - k));
  const auto st = merge_branches(s, {10, 15});
  CHECK(st.nodes_before == 6);
  CHECK(st.nodes_after == 2);
  CHECK(st.vertical_merges == 4);
  CHECK(st.horizontal_merges == 0);
  REQUIRE(s.size() == 2);
  CHECK(s.nodes[1].position == Vec3{0, 0, 5});
  CHECK(s.nodes[1].parent == 0);
  CHECK(s.nodes[1].radius == Approx(0.1));
  CHECK(s.validate().empty());
}

TEST_CASE("merge: a bend above alpha is kept, the straight parts around it go", "[merge]") {
  Skeleton s;
  std::uint32_t prev = add(s, {0, 0, 0}, kNoParent);
  for (int k = 1; k <= 3; ++k) prev = add(s, {0, 0, double(k)}, prev);
  const Vec3 bend = s.nodes[prev].position;
  for (int k = 1; k <= 2; ++k) prev = add(s, bend + in_xz(30, k), prev);
  const auto st = merge_branches(s, {10, 15});
  CHECK(st.vertical_merges == 3);
  REQUIRE(s.size() == 3);
  CHECK(s.nodes[1].position == bend);
  CHECK(length(s.nodes[2].position - (bend + in_xz(30, 2))) < 1e-12);
  // With alpha above the bend the whole chain becomes one segment.
  Skeleton t;
  prev = add(t, {0, 0, 0}, kNoParent);
  for (int k = 1; k <= 3; ++k) prev = add(t, {0, 0, double(k)}, prev);
  for (int k = 1; k <= 2; ++k) prev = add(t, bend + in_xz(30, k), prev);
  CHECK(merge_branches(t, {31, 15}).vertical_merges == 4);
  CHECK(t.size() == 2);
}

TEST_CASE("merge: leaf siblings within beta merge at their midpoint with the larger radius",
          "[merge]") {
  Skeleton s;
  const std::uint32_t root = add(s, {0, 0, 0}, kNoParent);
  const std::uint32_t fork = add(s, {0, 0, 1}, root);
  const Vec3 a = Vec3{0, 0, 1} + in_xz(20, 1), b = Vec3{0, 0, 1} + in_xz(30, 1);
  add(s, a, fork, 0.02);
  add(s, b, fork, 0.03);
  const std::uint32_t c = add(s, Vec3{0, 0, 1} + in_xz(-30, 1), fork, 0.04);
  OrganAnchor leaf;
  leaf.node = 3;  // on b, which is absorbed
  s.organs.push_back(leaf);
  const auto st = merge_branches(s, {10, 15});
  CHECK(st.horizontal_merges == 1);
  CHECK(st.vertical_merges == 0);
  CHECK(st.nodes_after == 4);
  REQUIRE(s.size() == 4);
  CHECK(length(s.nodes[2].position - (a + b) * 0.5) < 1e-12);
  CHECK(s.nodes[2].radius == 0.03);
  CHECK(s.nodes[3].position == Vec3{0, 0, 1} + in_xz(-30, 1));
  CHECK(s.nodes[3].radius == 0.04);
  REQUIRE(s.organs.size() == 1);
  CHECK(s.organs[0].node == 2);
  (void)c;
}

TEST_CASE("merge: siblings beyond beta and non-leaf siblings stay apart", "[merge]") {
  Skeleton s;
  const std::uint32_t root = add(s, {0, 0, 0}, kNoParent);
  const std::uint32_t fork = add(s, {0, 0, 1}, root);
  add(s, Vec3{0, 0, 1} + in_xz(20, 1), fork);
  add(s, Vec3{0, 0, 1} + in_xz(30, 1), fork);
  const Skeleton before = s;
  auto st = merge_branches(s, {10, 9.99});
  CHECK(st.horizontal_merges == 0);
  CHECK(s.size() == before.size());
  // A sibling with children of its own is not a leaf: Alg. 7 line 4.
  Skeleton t;
  const std::uint32_t r = add(t, {0, 0, 0}, kNoParent);
  const std::uint32_t f = add(t, {0, 0, 1}, r);
  const std::uint32_t inner = add(t, Vec3{0, 0, 1} + in_xz(20, 1), f);
  add(t, Vec3{0, 0, 1} + in_xz(25, 1), f);
  add(t, Vec3{0, 0, 1} + in_xz(20, 1) + in_xz(60, 1), inner);
  add(t, Vec3{0, 0, 1} + in_xz(20, 1) + in_xz(-60, 1), inner);
  st = merge_branches(t, {10, 15});
  CHECK(st.horizontal_merges == 0);
  CHECK(t.size() == 6);
}

TEST_CASE("merge: three leaves within beta merge twice", "[merge]") {
  Skeleton s;
  const std::uint32_t root = add(s, {0, 0, 0}, kNoParent);
  const std::uint32_t fork = add(s, {0, 0, 1}, root);
  for (double deg : {10.0, 15.0, 20.0}) add(s, Vec3{0, 0, 1} + in_xz(deg, 1), fork);
  const auto st = merge_branches(s, {5, 12});
  CHECK(st.horizontal_merges == 2);
  CHECK(s.size() == 3);
  // The first pair (10, 15) merges to ~12.5 deg, which then meets 20 deg (7.5 deg apart).
  const Vec3 m1 = (in_xz(10, 1) + in_xz(15, 1)) * 0.5;
  const Vec3 expect = Vec3{0, 0, 1} + (m1 + in_xz(20, 1)) * 0.5;
  CHECK(length(s.nodes[2].position - expect) < 1e-12);
}

TEST_CASE("merge: zero angles change nothing, empty and one-node skeletons pass", "[merge]") {
  Skeleton s;
  std::uint32_t prev = add(s, {0, 0, 0}, kNoParent);
  for (int k = 1; k <= 4; ++k) prev = add(s, {0, 0.1 * k * k, double(k)}, prev);
  const Skeleton before = s;
  const auto st = merge_branches(s, {0, 0});
  CHECK(st.nodes_after == st.nodes_before);
  REQUIRE(s.size() == before.size());
  for (std::size_t i = 0; i < s.size(); ++i) CHECK(s.nodes[i].position == before.nodes[i].position);
  Skeleton empty;
  CHECK(merge_branches(empty, {}).nodes_after == 0);
  Skeleton one;
  add(one, {1, 2, 3}, kNoParent);
  CHECK(merge_branches(one, {}).nodes_after == 1);
}

TEST_CASE("merge: bad input throws clear errors", "[merge]") {
  Skeleton s;
  add(s, {0, 0, 0}, 1);
  add(s, {0, 0, 1}, 0);  // a cycle
  CHECK_THROWS_WITH(merge_branches(s, {}), Catch::Contains("invalid skeleton"));
  Skeleton t;
  add(t, {0, 0, 0}, kNoParent);
  CHECK_THROWS_WITH(merge_branches(t, {-1, 10}), Catch::Contains("non-negative"));
  CHECK_THROWS(merge_branches(t, {10, std::nan("")}));
}

TEST_CASE("merge: children stored before parents are reordered parents first", "[merge]") {
  Skeleton s;
  SkeletonNode tip, mid, root;
  tip.position = {0, 0, 2};
  tip.parent = 1;
  mid.position = {0, 0, 1};
  mid.parent = 2;
  root.position = {0, 0, 0};
  s.add(tip), s.add(mid), s.add(root);
  const auto st = merge_branches(s, {10, 15});
  CHECK(st.vertical_merges == 1);
  REQUIRE(s.size() == 2);
  CHECK(s.nodes[0].parent == kNoParent);
  CHECK(s.nodes[1].position == Vec3{0, 0, 2});
}

TEST_CASE("merge: random trees stay valid and never grow over many seeds", "[merge]") {
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    Rng rng(seed);
    Skeleton s;
    add(s, {0, 0, 0}, kNoParent);
    const int n = 2 + int(rng.below(300));
    for (int i = 1; i < n; ++i) {
      const auto parent = std::uint32_t(rng.below(std::uint64_t(i)));
      const Vec3 step{rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3), rng.uniform(0.2, 1)};
      add(s, s.nodes[parent].position + step, parent, rng.uniform(0.01, 0.2));
    }
    for (int k = 0; k < 5; ++k) {
      OrganAnchor a;
      a.node = std::uint32_t(rng.below(std::uint64_t(n)));
      s.organs.push_back(a);
    }
    const double len = s.total_length();
    const MergeOptions o{rng.uniform(0, 40), rng.uniform(0, 40)};
    const auto st = merge_branches(s, o);
    INFO("seed " << seed);
    REQUIRE(s.validate().empty());
    CHECK(parents_first(s));
    CHECK(st.nodes_after == s.size());
    CHECK(st.nodes_before == std::size_t(n));
    CHECK(st.nodes_after + st.vertical_merges + st.horizontal_merges == st.nodes_before);
    CHECK(s.total_length() <= len + 1e-9);
    CHECK(s.organs.size() == 5);
    CHECK(s.roots().size() == 1);
  }
}
