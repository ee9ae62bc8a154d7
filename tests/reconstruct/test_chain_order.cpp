// Chains in order along their axes (reconstruct/bsg/chain_order.h): a chain that runs up and
// down its stem is put in order, a bent one is left alone, and the nodes of a fork's chain that
// lie behind the fork on the stem below join that stem, in order; on thick_oak from one station
// no chain of a stem is left running back from its fork.
#include <catch2/catch.hpp>
#include <cmath>

#include "../skeleton_infer/skeleton_fixtures.h"
#include "reconstruct/bsg/bsg.h"
#include "reconstruct/bsg/chain_order.h"
#include "tests/reconstruct/bsg_fixtures.h"
#include "tests/support/harness.h"

using namespace ramus;
using bsg::kNone;

namespace {

// A Bsg from positions, parents and one radius for every node.
bsg::Bsg make_bsg(const std::vector<Eigen::Vector3d>& pos, const std::vector<std::uint32_t>& parent,
                  double radius) {
  bsg::Bsg b;
  for (std::size_t i = 0; i < pos.size(); ++i) test::add_bsg_node(b, pos[i], parent[i], radius);
  return b;
}

// Every node's parent comes before it.
bool parents_first(const bsg::Bsg& b) {
  for (std::size_t v = 1; v < b.size(); ++v) {
    if (b.parent[v] >= v) return false;
  }
  return true;
}

// How many edges of radius >= r run down (their child lower than their parent by more than 1 cm).
int edges_down(const bsg::Bsg& b, double r) {
  int down = 0;
  for (std::size_t v = 1; v < b.size(); ++v) {
    if (b.radius[v] >= r && b.pos[v].z() < b.pos[b.parent[v]].z() - 0.01) ++down;
  }
  return down;
}

}  // namespace

TEST_CASE("chain order: a chain that runs up and down its stem is put in order", "[reconstruct]") {
  // Root, then 0.8, 0.4, 1.2, 0.6, 1.6 m up the z axis, then a tip at 2 m.
  const bsg::Bsg given = make_bsg(
      {{0, 0, 0}, {0, 0, 0.8}, {0, 0, 0.4}, {0, 0, 1.2}, {0, 0, 0.6}, {0, 0, 1.6}, {0, 0, 2.0}},
      {kNone, 0, 1, 2, 3, 4, 5}, 0.2);
  bsg::Bsg b = given;
  CHECK(bsg::order_chains_along_axes(b, 0.05) == 1);
  CHECK(edges_down(b, 0.05) == 0);
  CHECK(b.pos[1].z() == 0.4);
  CHECK(b.pos[4].z() == 1.2);
  // Thinner than the limit: left alone.
  b = given;
  CHECK(bsg::order_chains_along_axes(b, 0.5) == 0);
  CHECK(edges_down(b, 0.05) == 2);
}

TEST_CASE("chain order: a chain that turns back along another branch is left alone",
          "[reconstruct]") {
  // Out along x to 2 m, then back 5 cm above it to 1.1 m (two 2 cm whips joined at their tips,
  // as the BSG joins them where a scan from one side saw neither end). Every node lies near the
  // chord's line, but sorting along it would lace the two whips together.
  std::vector<Eigen::Vector3d> pos{{0, 0, 0}};
  std::vector<std::uint32_t> parent{kNone};
  for (int k = 1; k <= 10; ++k) pos.emplace_back(0.2 * k, 0, 0), parent.push_back(k - 1);
  for (int k = 1; k <= 9; ++k) {
    pos.emplace_back(2.0 - 0.1 * k, 0, 0.05);
    parent.push_back(std::uint32_t(pos.size() - 2));
  }
  const bsg::Bsg given = make_bsg(pos, parent, 0.02);
  bsg::Bsg b = given;
  CHECK(bsg::order_chains_along_axes(b, 0.01) == 0);
  CHECK(b.pos == given.pos);
  // The same chain on a stem ten times as thick steps back by less than two of its diameters:
  // a stem winding over its bark, put in order.
  b = make_bsg(pos, parent, 0.4);
  CHECK(bsg::order_chains_along_axes(b, 0.01) == 1);
}

TEST_CASE("chain order: the nodes of a fork's chain behind the fork join the stem below",
          "[reconstruct]") {
  // The stem: root, 1 m, fork at 3 m, whose stem chain runs back to 1.5 and 2.5 m before it goes
  // on up to 4 and 5 m, and a side branch from the fork out to x = 1.
  const bsg::Bsg given = make_bsg({{0, 0, 0},
                                   {0, 0, 1},
                                   {0, 0, 3},
                                   {0.02, 0, 1.5},
                                   {-0.02, 0, 2.5},
                                   {0, 0, 4},
                                   {0, 0, 5},
                                   {0.5, 0, 3.3},
                                   {1, 0, 3.6}},
                                  {kNone, 0, 1, 2, 3, 4, 5, 2, 7}, 0.3);
  bsg::Bsg b = given;
  CHECK(bsg::return_nodes_behind_forks(b, 0.05) == 2);
  REQUIRE(b.size() == given.size());
  CHECK(parents_first(b));
  CHECK(edges_down(b, 0.05) == 0);
  // The stem: 0, 1, 1.5, 2.5, 3 (the fork), then 4 and 5; the side branch still from the fork.
  std::vector<double> stem;
  for (std::uint32_t v = 0;;) {
    stem.push_back(b.pos[v].z());
    std::uint32_t next = kNone;
    for (std::uint32_t c = 0; c < b.size(); ++c) {
      if (b.parent[c] == v && std::abs(b.pos[c].x()) < 0.1) next = c;
    }
    if (next == kNone) break;
    v = next;
  }
  CHECK(stem == std::vector<double>{0, 1, 1.5, 2.5, 3, 4, 5});
  int from_fork = 0;
  for (std::uint32_t c = 0; c < b.size(); ++c) {
    if (b.parent[c] != kNone && b.pos[b.parent[c]].z() == 3) ++from_fork;
  }
  CHECK(from_fork == 2);
  // A chain that runs back off the stem (a drooping branch from the fork) stays where it is.
  bsg::Bsg droop =
      make_bsg({{0, 0, 0}, {0, 0, 1}, {0, 0, 3}, {0.8, 0, 2.6}, {1.2, 0, 2.9}, {0, 0, 4}},
               {kNone, 0, 1, 2, 3, 2}, 0.3);
  CHECK(bsg::return_nodes_behind_forks(droop, 0.05) == 0);
}

TEST_CASE("chain order: on thick_oak from one station no stem chain runs back from its fork",
          "[reconstruct]") {
  // Four to seven chains per reconstruction ran back from their fork down the stem below, up to
  // 3.8 stem radii, and the mesh turned back on itself there (a neck in the trunk at 180 degrees).
  Skeleton truth = skeleton_test::grow_example("examples/trees/thick_oak.ramus");
  scanner::turn_about_root(truth, 180);
  scanner::HarnessCase c;
  c.stations = 1;
  const scanner::HarnessResult r = scanner::run_harness(truth, c);
  REQUIRE(r.reconstructed.size() == 1);
  const Skeleton& s = r.reconstructed[0];
  const auto kids = s.children();
  int back = 0;
  for (std::uint32_t f = 0; f < s.size(); ++f) {
    if (kids.count(f) < 2 || s.nodes[f].radius < 0.2) continue;
    for (const std::uint32_t* it = kids.begin(f); it != kids.end(f); ++it) {
      // The chain from the fork: its first node and the node where it ends.
      const std::uint32_t v = *it;
      std::uint32_t end = v;
      while (kids.count(end) == 1) end = *kids.begin(end);
      const Vec3 u = normalized(s.nodes[end].position - s.nodes[f].position, Vec3{0, 0, 1});
      if (dot(s.nodes[v].position - s.nodes[f].position, u) < -s.nodes[f].radius) ++back;
    }
  }
  CHECK(back == 0);
}
