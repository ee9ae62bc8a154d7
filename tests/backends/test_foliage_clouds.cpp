// The leaf clouds of 2.5D foliage impostors (backends/mesh/foliage_clouds.h, Burkus 6): every
// leaf card lies inside the cloud it belongs to, the clouds are few and deterministic, and the
// glTF writer records them on the scene's root node in the scene's frame (y up, local origin
// added) as {"ramus_foliage": {"clouds": [{"centre", "radius"}]}}.
#include <catch2/catch.hpp>

#include "backends/mesh/foliage_clouds.h"
#include "backends/mesh/gltf_writer.h"
#include "tests/backends/glb_reader.h"
#include "tests/mesh/synthetic_tree.h"

using namespace ramus;
using namespace ramus::mesh;
using ramus::testing::item;

namespace {

TreeMesh lod0(const Skeleton& s, bool wind = false) {
  MeshOptions o;
  o.wind = wind;
  return build_tree_mesh(s, o);
}

// The clouds the glTF's root node records, as (centre, radius) in the scene's frame.
std::vector<FoliageCloud> written_clouds(const std::vector<TreeMesh>& lods) {
  const testing::Glb g = testing::read_glb(encode_gltf(lods, true).main);
  const int root = int(item(g.at("scenes"), 0).find("nodes")->items.at(0).number);
  const auto* extras = item(g.at("nodes"), root).find("extras");
  const auto* foliage = extras ? extras->find("ramus_foliage") : nullptr;
  std::vector<FoliageCloud> out;
  if (foliage == nullptr) return out;
  for (const auto& c : foliage->find("clouds")->items) {
    const auto& p = c.find("centre")->items;
    out.push_back({{p.at(0).number, p.at(1).number, p.at(2).number}, c.find("radius")->number});
  }
  return out;
}

}  // namespace

TEST_CASE("every leaf card lies inside its cloud, and the clouds are few", "[gltf][foliage]") {
  const TreeMesh m = lod0(testing::synthetic_tree(11, 600));
  const std::size_t faces = m.leaves.positions.size() / 4;
  REQUIRE(faces > 100);
  const std::vector<FoliageCloud> clouds = foliage_clouds(m.leaves);
  CHECK(int(clouds.size()) == foliage_cloud_count(faces / 2));
  CHECK(clouds.size() >= 2);
  // Each face belongs to the cloud whose centre is nearest its own centre (k-means' assignment).
  std::vector<std::size_t> members(clouds.size(), 0);
  double worst = -1;
  for (std::size_t f = 0; f < faces; ++f) {
    Vec3 c;
    for (int k = 0; k < 4; ++k) c += Vec3(m.leaves.positions[4 * f + k]) * 0.25;
    std::size_t best = 0;
    for (std::size_t i = 1; i < clouds.size(); ++i)
      if (distance(c, clouds[i].centre) < distance(c, clouds[best].centre)) best = i;
    ++members[best];
    for (int k = 0; k < 4; ++k)
      worst = std::max(worst, distance(Vec3(m.leaves.positions[4 * f + k]), clouds[best].centre) -
                                  clouds[best].radius);
  }
  CHECK(worst <= 1e-9);
  for (std::size_t n : members) CHECK(n > 0);
  // Clouds are local: each is much smaller than the crown.
  double crown = 0;
  for (const Vec3f& p : m.leaves.positions)
    crown = std::max(crown, distance(Vec3(p), clouds[0].centre));
  for (const FoliageCloud& c : clouds) CHECK(c.radius < 0.6 * crown);
}

TEST_CASE("leaf clouds are the same for the same mesh and seed", "[gltf][foliage]") {
  const TreeMesh m = lod0(testing::synthetic_tree(4, 400));
  const auto a = foliage_clouds(m.leaves, 3), b = foliage_clouds(m.leaves, 3);
  REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    CHECK(a[i].centre == b[i].centre);
    CHECK(a[i].radius == b[i].radius);
  }
  CHECK(foliage_clouds(MeshPart{}).empty());
  CHECK(foliage_cloud_count(0) == 0);
  CHECK(foliage_cloud_count(1) == 1);
  CHECK(foliage_cloud_count(100) == 10);
  CHECK(foliage_cloud_count(1000000) == kMaxFoliageClouds);
}

TEST_CASE("the glTF records the clouds in the scene's frame, local origin and wind or not",
          "[gltf][foliage]") {
  const Skeleton here = testing::synthetic_tree(7, 400);
  const Vec3 utm{1180000.37, 2860000.81, 312.4};
  Skeleton there = here;
  for (SkeletonNode& n : there.nodes) n.position += utm;
  for (OrganAnchor& a : there.organs) a.position += utm;
  for (const bool wind : {false, true}) {
    for (const Skeleton* s : std::vector<const Skeleton*>{&here, &there}) {
      INFO("wind " << wind << ", georeferenced " << (s == &there));
      const TreeMesh m = lod0(*s, wind);
      const std::vector<FoliageCloud> want = foliage_clouds(m.leaves);
      const std::vector<FoliageCloud> got = written_clouds({m});
      REQUIRE(got.size() == want.size());
      REQUIRE(!got.empty());
      for (std::size_t i = 0; i < got.size(); ++i) {
        const Vec3 w = m.origin + want[i].centre;
        CHECK(distance(got[i].centre, Vec3{w.x, w.z, -w.y}) <= 1e-4);  // 0.1 mm rounding
        CHECK(got[i].radius >= want[i].radius);                        // rounded up
        CHECK(got[i].radius - want[i].radius <= 1e-4);
      }
    }
  }
  // A tree without leaves has no clouds.
  Skeleton bare = here;
  bare.organs.clear();
  CHECK(written_clouds({lod0(bare)}).empty());
}
