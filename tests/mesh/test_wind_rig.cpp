// The wind skin (mesh/wind_rig.h): joints follow the branch chains within the budget,
// parents before children, the trunk's base joint never moves, every vertex is bound to joints
// that exist with weights in [0, 1], and the trunk leans furthest at a quarter period.
#include <catch2/catch.hpp>
#include <cmath>

#include "mesh/tree_mesh.h"
#include "tests/mesh/synthetic_tree.h"

using namespace ramus;
using namespace ramus::mesh;

TEST_CASE("the wind rig follows the chains and keeps the trunk base fixed", "[mesh][wind]") {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Skeleton s = testing::synthetic_tree(seed, 100 + 40 * seed);
    MeshOptions o;
    o.wind = true;
    o.lod_count = 3;
    o.wind_rig.max_joints = 8 + int(seed) * 4;
    const std::vector<TreeMesh> lods = build_tree_lods(s, o);
    const WindRig& rig = lods.front().wind_rig;
    INFO("seed " << seed);
    REQUIRE(rig.joints.size() >= 2);
    CHECK(rig.joints.size() <= std::size_t(o.wind_rig.max_joints));
    CHECK(rig.joints[0].parent == kNoJoint);
    CHECK(rig.joints[0].amplitude == 0);  // the trunk's base
    CHECK(rig.animated_joints() > 0);
    CHECK(rig.node_binding.size() == s.nodes.size());
    for (std::size_t j = 1; j < rig.joints.size(); ++j) {
      if (rig.joints[j].parent != kNoJoint) CHECK(rig.joints[j].parent < j);
      CHECK(std::abs(length(rig.joints[j].axis) - 1) < 1e-9);
    }
    // Joint 1 is the trunk's second joint: it leans furthest at a quarter period.
    CHECK(rig.angle(1, rig.period / 4) == Approx(rig.joints[1].amplitude));
    CHECK(rig.angle(1, 0) == Approx(0).margin(1e-12));
    // The root node's vertices follow the fixed base joint alone.
    const JointBinding root = rig.binding(s.roots().front());
    CHECK(root.a == 0);
    CHECK(root.t == 0);
    for (const TreeMesh& m : lods) {
      CHECK(m.wind_rig.joints.size() == rig.joints.size());
      for (const MeshPart* part : {&m.bark, &m.leaves}) {
        REQUIRE(part->skin_node.size() == part->vertex_count());
        for (std::uint32_t n : part->skin_node) {
          const JointBinding b = rig.binding(n);
          CHECK(b.a < rig.joints.size());
          CHECK(b.b < rig.joints.size());
          CHECK((b.t >= 0 && b.t <= 1));
        }
      }
    }
  }
}

TEST_CASE("without --wind there is no rig", "[mesh][wind]") {
  const TreeMesh m = build_tree_mesh(testing::synthetic_tree(3, 200), {});
  CHECK(m.wind_rig.empty());
}
