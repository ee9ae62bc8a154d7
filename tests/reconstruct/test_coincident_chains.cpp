// Chains on one axis joined into one (reconstruct/bsg/coincident_chains.h): two copies of a
// stem from the root, each going on into its own limb, become one stem with both limbs; chains
// apart, a limb leaving at an angle and a chain that comes back round a loop stay as they are;
// on the 14 m harness tree from three stations the skeleton's length comes down to the truth's.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "reconstruct/bsg/coincident_chains.h"
#include "tests/reconstruct/bsg_fixtures.h"
#include "tests/reconstruct/reconstruct_fixtures.h"
#include "tests/support/harness.h"

using namespace ramus;
using bsg::Bsg;
using bsg::kNone;
using test::add_bsg_node;

namespace {

double total_length(const Bsg& b) {
  double l = 0;
  for (std::uint32_t v = 1; v < b.size(); ++v) l += (b.pos[v] - b.pos[b.parent[v]]).norm();
  return l;
}

int tips(const Bsg& b) {
  std::vector<int> children(b.size(), 0);
  for (std::uint32_t v = 1; v < b.size(); ++v) ++children[b.parent[v]];
  return int(std::count(children.begin(), children.end(), 0));
}

bool parents_first(const Bsg& b) {
  for (std::uint32_t v = 1; v < b.size(); ++v) {
    if (b.parent[v] >= v) return false;
  }
  return true;
}

// A stem of radius 0.3 m up z, as two chains from the root `apart` metres across, as two paths
// up the bark step: the first with nodes every 0.2 m up to 2 m, then a limb of radius 0.1 m
// along +x at 45 degrees (five nodes 0.3 m apart); the second with nodes every 0.25 m from
// 0.12 m up to 3.12 m (none level with one of the first), then a limb along -x.
Bsg two_copies(double apart) {
  Bsg b;
  const std::uint32_t root = add_bsg_node(b, {0, 0, 0}, kNone, 0.3);
  const Eigen::Vector3d out_x = Eigen::Vector3d(1, 0, 1).normalized();
  const Eigen::Vector3d out_minus_x = Eigen::Vector3d(-1, 0, 1).normalized();
  std::uint32_t up = root;
  for (int k = 1; k <= 10; ++k) up = add_bsg_node(b, {0, 0, 0.2 * k}, up, 0.3);
  for (int k = 1; k <= 5; ++k) {
    up = add_bsg_node(b, Eigen::Vector3d(0, 0, 2) + 0.3 * k * out_x, up, 0.1);
  }
  up = root;
  for (int k = 1; k <= 13; ++k) up = add_bsg_node(b, {apart, 0, 0.25 * k - 0.13}, up, 0.3);
  for (int k = 1; k <= 5; ++k) {
    up = add_bsg_node(b, Eigen::Vector3d(apart, 0, 3.12) + 0.3 * k * out_minus_x, up, 0.1);
  }
  return b;
}

bsg::CoincidentChainParams params() {
  bsg::CoincidentChainParams p;
  p.spacing = 0.02;
  return p;
}

}  // namespace

TEST_CASE("coincident chains: two copies of a stem become one stem carrying both limbs",
          "[reconstruct]") {
  Bsg b = two_copies(0.01);
  const double before = total_length(b);
  CHECK(before == Approx(2.0 + 3.12 + 1.5 + 1.5).margin(0.02));
  // The second copy's eight nodes below 2 m go onto the first's edges; from 2.12 m it goes on
  // from its node at 1.87 m, on the stem's one chain, to its limb.
  CHECK(bsg::join_coincident_chains(b, params()) == 8);
  CHECK(parents_first(b));
  CHECK(tips(b) == 2);
  CHECK(total_length(b) == Approx(2.0 + 1.25 + 1.5 + 1.5).margin(0.02));
  int root_children = 0;
  for (std::uint32_t v = 1; v < b.size(); ++v) {
    if (b.parent[v] == 0) ++root_children;
    if (b.radius[v] == 0.3 && b.pos[v].z() < 2.0) CHECK(std::abs(b.pos[v].x()) < 1e-9);
  }
  CHECK(root_children == 1);
  // Nothing to join the second time.
  CHECK(bsg::join_coincident_chains(b, params()) == 0);
}

TEST_CASE("coincident chains: chains apart, limbs leaving at an angle and loops stay",
          "[reconstruct]") {
  // 0.1 m apart is more than a quarter of the 0.3 m radius: two stems side by side.
  Bsg apart = two_copies(0.1);
  const Bsg given = apart;
  CHECK(bsg::join_coincident_chains(apart, params()) == 0);
  CHECK(apart.pos == given.pos);
  CHECK(apart.parent == given.parent);

  // A stem and a chain that leaves it at the root at 45 degrees: its first node is within the
  // tolerance but does not run the stem's way.
  Bsg fork;
  const std::uint32_t root = add_bsg_node(fork, {0, 0, 0}, kNone, 0.3);
  std::uint32_t up = root;
  for (int k = 1; k <= 5; ++k) up = add_bsg_node(fork, {0, 0, 0.2 * k}, up, 0.3);
  up = root;
  for (int k = 1; k <= 5; ++k) up = add_bsg_node(fork, {0.05 * k, 0, 0.05 * k}, up, 0.1);
  CHECK(bsg::join_coincident_chains(fork, params()) == 0);

  // A chain that goes up 2 m and back down beside itself 0.01 m away: the way down runs along
  // the way up, but the way up lies behind it on the tree, not ahead of it.
  Bsg loop;
  up = add_bsg_node(loop, {0, 0, 0}, kNone, 0.3);
  for (int k = 1; k <= 10; ++k) up = add_bsg_node(loop, {0, 0, 0.2 * k}, up, 0.3);
  for (int k = 10; k >= 5; --k) up = add_bsg_node(loop, {0.01, 0, 0.2 * k - 0.1}, up, 0.3);
  CHECK(bsg::join_coincident_chains(loop, params()) == 0);
}

// Measured with and without the step (`bench_reconstruct accuracy --stations 3 thick
// --tree-seed 2 [--opt join_coincident=0]`): length 1.41 -> 1.06 x the truth's, every class
// median within 0.002 r, precision and recall within 2 x radius the same.
TEST_CASE("coincident chains: the 14 m tree from three stations is as long as the truth",
          "[accuracy]") {
  const Skeleton truth = test::thick_tree(2, 14.0, 0.6);
  scanner::HarnessCase c;
  c.stations = 3;
  const scanner::HarnessResult joined = scanner::run_harness(truth, c);
  ReconstructOptions off;
  off.join_coincident = false;
  const scanner::HarnessResult copies = scanner::run_harness(truth, c, off);
  INFO("length " << joined.at_radius.length_ratio << ", without the step "
                 << copies.at_radius.length_ratio);
  REQUIRE(joined.trees == 1);
  CHECK(joined.at_radius.length_ratio < 1.15);
  CHECK(copies.at_radius.length_ratio > 1.3);
  CHECK(joined.at_radius.precision >= copies.at_radius.precision - 0.005);
  CHECK(joined.at_radius.recall >= copies.at_radius.recall - 0.005);
}
