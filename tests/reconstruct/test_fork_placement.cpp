// Forks moved from the crotch to where the axes meet (reconstruct/bsg/fork_placement.h).
#include <catch2/catch.hpp>
#include <cmath>

#include "reconstruct/bsg/fork_placement.h"
#include "tests/reconstruct/bsg_fixtures.h"

using namespace ramus::bsg;
using ramus::test::add_bsg_node;

namespace {

// A stem of radius 0.2 along z (nodes every 0.25 m up to 2.5 m) and a limb of radius 0.1 whose
// axis leaves the stem's axis at z = 1 at 40 degrees; the BSG hung the limb from the crotch node
// at z = 1.5 (as the shortest paths along the bark do). Every node is fitted.
Bsg crotch(std::uint32_t& limb, std::uint32_t& crotch_node) {
  Bsg b;
  std::uint32_t up = add_bsg_node(b, {0, 0, 0}, kNone, 0.2);
  for (int k = 1; k <= 10; ++k) {
    up = add_bsg_node(b, {0, 0, 0.25 * k}, up, 0.2);
    if (k == 6) crotch_node = up;
  }
  const Eigen::Vector3d d(std::sin(40 * M_PI / 180), 0, std::cos(40 * M_PI / 180));
  up = crotch_node;
  for (int k = 0; k < 4; ++k) {
    up = add_bsg_node(b, Eigen::Vector3d(0, 0, 1) + (0.6 + 0.3 * k) * d, up, 0.1);
    if (k == 0) limb = up;
  }
  return b;
}

}  // namespace

TEST_CASE("fork placement: a limb hung from the crotch moves to where the axes meet",
          "[reconstruct]") {
  std::uint32_t limb = 0, crotch_node = 0;
  Bsg b = crotch(limb, crotch_node);
  const Eigen::Vector3d limb_pos = b.pos[limb];
  std::vector<std::uint8_t> fitted(b.size(), 1);
  CHECK(place_forks(b, fitted, 0.02) == 1);
  REQUIRE(fitted.size() == b.size());
  for (std::uint32_t v = 1; v < b.size(); ++v) CHECK(b.parent[v] < v);
  std::uint32_t moved = kNone;
  for (std::uint32_t v = 0; v < b.size(); ++v) {
    if ((b.pos[v] - limb_pos).norm() < 1e-9) moved = v;
  }
  REQUIRE(moved != kNone);
  // The stem node at z = 1 (index 4 before and after: parents first, stem first).
  CHECK((b.pos[b.parent[moved]] - Eigen::Vector3d(0, 0, 1)).norm() < 1e-9);
}

TEST_CASE("fork placement: unfitted limbs and forks already on the axis stay", "[reconstruct]") {
  std::uint32_t limb = 0, crotch_node = 0;
  Bsg b = crotch(limb, crotch_node);
  std::vector<std::uint8_t> fitted(b.size(), 1);
  fitted[limb] = 0;  // no axis to continue
  CHECK(place_forks(b, fitted, 0.02) == 0);
  CHECK(b.parent[limb] == crotch_node);
  // A limb whose axis meets the stem at its fork.
  Bsg c;
  std::uint32_t up = add_bsg_node(c, {0, 0, 0}, kNone, 0.2);
  for (int k = 1; k <= 8; ++k) up = add_bsg_node(c, {0, 0, 0.25 * k}, up, 0.2);
  std::uint32_t side = 4;
  for (int k = 1; k <= 3; ++k) side = add_bsg_node(c, {0.3 * k, 0, 1 + 0.3 * k}, side, 0.1);
  std::vector<std::uint8_t> all(c.size(), 1);
  CHECK(place_forks(c, all, 0.02) == 0);
}

TEST_CASE("fork placement: a limb whose axis meets the stem between two nodes gets a new fork",
          "[reconstruct]") {
  // The limb's nodes come before the stem's continuation (the fork's children in that order),
  // and its axis meets the stem at z = 1.6, between the stem nodes at 1.5 (the fork) and 1.75.
  Bsg b;
  std::uint32_t fork = add_bsg_node(b, {0, 0, 0}, kNone, 0.2);
  for (int k = 1; k <= 6; ++k) fork = add_bsg_node(b, {0, 0, 0.25 * k}, fork, 0.2);
  const Eigen::Vector3d d(std::sin(40 * M_PI / 180), 0, std::cos(40 * M_PI / 180));
  std::uint32_t up = fork;
  for (int k = 0; k < 4; ++k)
    up = add_bsg_node(b, Eigen::Vector3d(0, 0, 1.6) + (0.3 + 0.3 * k) * d, up, 0.1);
  up = fork;
  for (int k = 7; k <= 10; ++k) up = add_bsg_node(b, {0, 0, 0.25 * k}, up, 0.2);
  const std::size_t before = b.size();
  std::vector<std::uint8_t> fitted(b.size(), 1);
  CHECK(place_forks(b, fitted, 0.02) == 1);
  REQUIRE(b.size() == before + 1);
  REQUIRE(fitted.size() == b.size());
  std::uint32_t limb = kNone, split = kNone;
  for (std::uint32_t v = 0; v < b.size(); ++v) {
    if ((b.pos[v] - (Eigen::Vector3d(0, 0, 1.6) + 0.3 * d)).norm() < 1e-9) limb = v;
    if ((b.pos[v] - Eigen::Vector3d(0, 0, 1.6)).norm() < 0.01) split = v;
  }
  REQUIRE(limb != kNone);
  REQUIRE(split != kNone);
  CHECK(b.parent[limb] == split);
  for (std::uint32_t v = 1; v < b.size(); ++v) CHECK(b.parent[v] < v);
  // The stem still runs through the new node: 1.5 -> 1.6 -> 1.75.
  std::size_t stem_children = 0;
  for (std::uint32_t v = 0; v < b.size(); ++v) {
    if (b.parent[v] == split && std::abs(b.pos[v].x()) < 1e-9) ++stem_children;
  }
  CHECK(stem_children == 1);
}
