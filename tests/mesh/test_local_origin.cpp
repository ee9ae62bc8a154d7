// The local origin of a mesh (mesh/local_origin.h): none for trees near the origin, a
// whole-unit base point for georeferenced ones, carried by every level of detail.
#include <catch2/catch.hpp>

#include "mesh/local_origin.h"
#include "mesh/tree_mesh.h"
#include "tests/mesh/synthetic_tree.h"

using namespace ramus;
using namespace ramus::mesh;

namespace {

Skeleton moved(Skeleton s, const Vec3& by) {
  for (SkeletonNode& n : s.nodes) n.position += by;
  for (OrganAnchor& a : s.organs) a.position += by;
  return s;
}

}  // namespace

TEST_CASE("local origin: zero within float32's millimetre range, else the rounded base",
          "[mesh][origin]") {
  const Skeleton s = ramus::testing::synthetic_tree(2, 200);
  CHECK(local_origin(s) == Vec3{});
  CHECK(local_origin(moved(s, {9000, -9000, 100})) == Vec3{});  // still within 16384
  const Skeleton far = moved(s, {1180000.37, 2860000.81, 312.4});
  const Vec3 o = local_origin(far);
  Vec3 lo, hi;
  far.bounds(lo, hi);
  CHECK(o.x == std::round((lo.x + hi.x) / 2));
  CHECK(o.y == std::round((lo.y + hi.y) / 2));
  CHECK(o.z == std::round(lo.z));  // the tree's base sits near the local origin
  const Skeleton local = relative_to(far, o);
  for (std::size_t i = 0; i < s.nodes.size(); ++i)
    CHECK(distance(local.nodes[i].position + o, far.nodes[i].position) < 1e-9);
  CHECK(local.organs.size() == far.organs.size());
}

TEST_CASE("local origin: every level records it and the mesh is the same shape", "[mesh][origin]") {
  const Skeleton s = ramus::testing::synthetic_tree(6, 300);
  const Vec3 utm{-501234.5, 4412345.25, 1200};
  MeshOptions o;
  o.lod_count = 3;
  const auto near = build_tree_lods(s, o);
  const auto far = build_tree_lods(moved(s, utm), o);
  REQUIRE(far.size() == 3);
  for (std::size_t k = 0; k < far.size(); ++k) {
    CHECK(near[k].origin == Vec3{});
    CHECK(far[k].origin == far[0].origin);
    REQUIRE(far[k].bark.positions.size() == near[k].bark.positions.size());
    REQUIRE(far[k].leaves.positions.size() == near[k].leaves.positions.size());
    double worst = 0;
    for (std::size_t i = 0; i < near[k].bark.positions.size(); ++i) {
      const Vec3 world = far[k].origin + Vec3(far[k].bark.positions[i]);
      worst = std::max(worst, distance(world, Vec3(near[k].bark.positions[i]) + utm));
    }
    CHECK(worst < 1e-3);
  }
  CHECK(build_tree_mesh(moved(s, utm), {}).origin == far[0].origin);
}
