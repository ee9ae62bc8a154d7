// How the glTF writer places a tree for engines: y up (spec 3.4) with the z-up mesh turned by
// (x, y, z) -> (x, z, -y), a georeferenced mesh's local origin as the root node's translation,
// and the levels of detail behind MSFT_lod so that only LOD0 is in the scene. Read back from
// the .glb bytes with a JSON reader of our own (tests/backends/glb_reader.h).
#include <catch2/catch.hpp>

#include "backends/mesh/gltf_writer.h"
#include "tests/backends/glb_reader.h"
#include "tests/mesh/synthetic_tree.h"

using namespace ramus;
using namespace ramus::mesh;
using ramus::testing::Glb;
using ramus::testing::item;

namespace {

Glb glb_of(const std::vector<TreeMesh>& lods) {
  return ramus::testing::read_glb(encode_gltf(lods, true).main);
}

std::vector<TreeMesh> lods_of(const Skeleton& s, int count) {
  MeshOptions o;
  o.lod_count = count;
  return build_tree_lods(s, o);
}

}  // namespace

TEST_CASE("glTF positions and normals are the z-up mesh turned to y up", "[gltf][placement]") {
  const std::vector<TreeMesh> lods = lods_of(ramus::testing::synthetic_tree(3, 300), 1);
  const Glb g = glb_of(lods);
  const auto pos = read_vec3(g, attribute_accessor(g, 0, 0, "POSITION"));
  const auto nrm = read_vec3(g, attribute_accessor(g, 0, 0, "NORMAL"));
  REQUIRE(pos.size() == lods[0].bark.positions.size());
  for (std::size_t i = 0; i < pos.size(); ++i) {
    const Vec3f& p = lods[0].bark.positions[i];
    const Vec3f& n = lods[0].bark.normals[i];
    CHECK(pos[i] == Vec3f{p.x, p.z, -p.y});  // exact: a permutation and a sign
    CHECK(nrm[i] == Vec3f{n.x, n.z, -n.y});
  }
  // The rotation keeps handedness: a triangle's winding gives the same facing as its normals.
  const auto& idx = lods[0].bark.indices;
  double agree = 0, total = 0;
  for (std::size_t t = 0; t + 2 < idx.size(); t += 3) {
    const Vec3 a(pos[idx[t]]), b(pos[idx[t + 1]]), c(pos[idx[t + 2]]);
    const Vec3 face = cross(b - a, c - a);
    if (length(face) < 1e-9) continue;
    total += 1;
    agree += dot(face, Vec3(nrm[idx[t]])) > 0 ? 1 : 0;
  }
  CHECK(agree / total > 0.99);
  // A tree near the origin needs no translation.
  CHECK(item(g.at("nodes"), 0).find("translation") == nullptr);
}

TEST_CASE("MSFT_lod: the scene shows LOD0, the root names the coarser levels", "[gltf][lod]") {
  const Glb g = glb_of(lods_of(ramus::testing::synthetic_tree(5, 500), 4));
  const auto& used = g.at("extensionsUsed");
  REQUIRE(used.items.size() == 1);
  CHECK(used.items[0].text == "MSFT_lod");
  CHECK(g.json.find("extensionsRequired") == nullptr);  // viewers without it draw LOD0
  const auto& scene = item(g.at("scenes"), 0);
  REQUIRE(scene.find("nodes")->items.size() == 1);
  const int root = int(scene.find("nodes")->items[0].number);
  const auto& nodes = g.at("nodes");
  REQUIRE(nodes.items.size() == 4);
  const auto& r = item(nodes, root);
  CHECK(r.find("children") == nullptr);  // no level is drawn beside another
  CHECK(item(g.at("meshes"), int(r.find("mesh")->number)).find("name")->text == "tree_LOD0");
  const auto& ids = r.find("extensions")->find("MSFT_lod")->find("ids")->items;
  REQUIRE(ids.size() == 3);
  const auto& coverage = r.find("extras")->find("MSFT_screencoverage")->items;
  REQUIRE(coverage.size() == 4);  // one threshold per level, LOD0 included
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const int id = int(ids[k].number);
    CHECK(id != root);
    const auto& level = item(nodes, id);
    CHECK(item(g.at("meshes"), int(level.find("mesh")->number)).find("name")->text ==
          "tree_LOD" + std::to_string(k + 1));
    CHECK(coverage[k + 1].number < coverage[k].number);  // coarser levels for smaller trees
  }
  CHECK(coverage.back().number == 0);  // the coarsest level is never switched off by the hint
  // A single level has no extension at all.
  const Glb one = glb_of(lods_of(ramus::testing::synthetic_tree(5, 500), 1));
  CHECK(one.json.find("extensionsUsed") == nullptr);
  CHECK(item(one.at("nodes"), 0).find("extras") == nullptr);
}

TEST_CASE("a georeferenced tree keeps millimetres: local vertices plus the root translation",
          "[gltf][placement]") {
  // The same tree at the origin and at UTM-sized coordinates (zone 32N eastings/northings).
  const Skeleton here = ramus::testing::synthetic_tree(7, 400);
  const Vec3 utm{1180000.37, 2860000.81, 312.4};
  Skeleton there = here;
  for (SkeletonNode& n : there.nodes) n.position += utm;
  for (OrganAnchor& a : there.organs) a.position += utm;
  const std::vector<TreeMesh> near = lods_of(here, 2), far = lods_of(there, 2);
  const Glb g = glb_of(far);
  const auto& nodes = g.at("nodes");
  REQUIRE(nodes.items.size() == 2);
  for (const auto& node : nodes.items) {  // every level stands in the root's place
    const auto* t = node.find("translation");
    REQUIRE(t != nullptr);
    const Vec3 want{far[0].origin.x, far[0].origin.z, -far[0].origin.y};
    CHECK(Vec3(t->items[0].number, t->items[1].number, t->items[2].number) == want);
  }
  const auto* t = item(nodes, 0).find("translation");
  const Vec3 offset{t->items[0].number, t->items[1].number, t->items[2].number};
  // World position (y up) of each written vertex against the double-precision position of the
  // same vertex: the tree at the origin (exact in float near 0) moved by `utm`.
  const auto pos = read_vec3(g, attribute_accessor(g, 0, 0, "POSITION"));
  REQUIRE(pos.size() == near[0].bark.positions.size());
  double worst = 0, naive = 0;
  for (std::size_t i = 0; i < pos.size(); ++i) {
    const Vec3 exact = Vec3(near[0].bark.positions[i]) + utm;
    const Vec3 want{exact.x, exact.z, -exact.y};
    worst = std::max(worst, distance(offset + Vec3(pos[i]), want));
    naive = std::max(naive, distance(Vec3(Vec3f(exact)), exact));  // float32 world coordinates
  }
  INFO("worst " << worst << " m with the local origin, " << naive << " m in plain float32");
  CHECK(worst < 1e-3);
  CHECK(naive > 1e-2);  // the failure the local origin prevents
}
