// Tree bases (Livny et al. 4.1) on simulated scans of the bundled grammar trees: each scan holds
// one tree, and the base finder must find exactly one, whatever droops, hangs or branches low.
#include <catch2/catch.hpp>
#include <string>

#include "../skeleton_infer/skeleton_fixtures.h"
#include "tests/support/harness.h"

using namespace ramus;

namespace {

Skeleton grow_example(const std::string& name) {
  return skeleton_test::grow_example("examples/trees/" + name + ".ramus");
}

}  // namespace

TEST_CASE("reconstruct bases: one tree in each one-station scan of the grammar trees",
          "[reconstruct_bases]") {
  // broadleaf: low drooping limbs; conifer: a whorl 0.7 m above the ground; weeping: whips that
  // hang to the ground. Each used to add one or more false trunks.
  for (const std::string name : {"broadleaf", "conifer", "weeping"}) {
    const Skeleton truth = grow_example(name);
    REQUIRE(truth.size() > 100);
    scanner::HarnessCase c;
    c.stations = 1;
    c.density = 1500;
    const scanner::HarnessResult r = scanner::run_harness(truth, c);
    INFO(name << ": " << r.points << " points");
    CHECK(r.trees == 1);
    // The trunk base is kept (terrain removal must not eat it): the reconstructed root is within
    // a trunk radius of the true one.
    REQUIRE_FALSE(r.reconstructed.empty());
    const Vec3 root = r.reconstructed[0].nodes[0].position;
    CHECK(distance(root, truth.nodes[0].position) < 2 * truth.nodes[0].radius);
  }
}

TEST_CASE("reconstruct bases: the weeping tree from three stations is still one tree",
          "[reconstruct_bases]") {
  // Three stations see every whip that reaches the ground: the hardest single-tree case.
  const Skeleton truth = grow_example("weeping");
  scanner::HarnessCase c;
  c.stations = 3;
  c.density = 1500;
  const scanner::HarnessResult r = scanner::run_harness(truth, c);
  CHECK(r.trees == 1);
}
