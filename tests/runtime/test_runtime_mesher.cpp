// The mesher block of the C API (runtime/ramus_mesher.cpp): in ramus's own z-up frame the arrays
// are TreeMesh's (build_tree_lods, the same code `ramus build` runs; the y-up arrays are compared
// with `ramus build`'s .glb in test_grow_mesh_example.cpp); the frames and orders are the
// skeleton's; bad options and out-of-range arguments give errors, not crashes.
#include <catch2/catch.hpp>
#include <cstring>
#include <memory>
#include <string>

#include "compiler/grow.h"
#include "compiler/pipeline.h"
#include "formats/rmb/rmb_codec.h"
#include "grammar/loader.h"
#include "mesh/tree_mesh.h"
#include "runtime/ramus_runtime.h"

namespace {

using GrammarPtr = std::unique_ptr<ramus_grammar, decltype(&ramus_free_grammar)>;
using SkeletonPtr = std::unique_ptr<ramus_skeleton, decltype(&ramus_free_skeleton)>;
using MeshPtr = std::unique_ptr<ramus_mesh, decltype(&ramus_free_mesh)>;

std::string path_of(const std::string& example) {
  return std::string(RAMUS_SOURCE_DIR) + "/examples/" + example;
}

struct Grown {
  ramus::Skeleton source;  // grow_file's tree
  GrammarPtr grammar{nullptr, ramus_free_grammar};
  SkeletonPtr skeleton{nullptr, ramus_free_skeleton};  // the runtime's
};

Grown grow_both(const std::string& example) {
  ramus::SourceManager sm;
  ramus::DiagnosticSink diags;
  Grown g;
  g.source = ramus::grow_file(path_of(example), {}, sm, diags);
  const std::string bytes = ramus::encode_rmb(ramus::lower_file(path_of(example), {}, sm, diags));
  g.grammar.reset(ramus_load(bytes.data(), bytes.size(), nullptr, 0));
  REQUIRE(g.grammar);
  g.skeleton.reset(
      ramus_grow(g.grammar.get(), -1, ramus_grammar_seed(g.grammar.get()), nullptr, 0));
  REQUIRE(g.skeleton);
  return g;
}

template <typename T, typename U>
bool same_bytes(const T* got, const std::vector<U>& want, std::size_t values) {
  REQUIRE(values * sizeof(T) == want.size() * sizeof(U));
  return values == 0 || std::memcmp(got, want.data(), values * sizeof(T)) == 0;
}

void require_part(const ramus_mesh* m, int lod, int part, const ramus::mesh::MeshPart& want) {
  INFO("level " << lod << " part " << part);
  const std::size_t n = want.vertex_count();
  REQUIRE(ramus_mesh_vertex_count(m, lod, part) == n);
  REQUIRE(ramus_mesh_index_count(m, lod, part) == want.indices.size());
  if (want.empty()) {
    CHECK(ramus_mesh_positions(m, lod, part) == nullptr);
    CHECK(ramus_mesh_indices(m, lod, part) == nullptr);
    return;
  }
  CHECK(same_bytes(ramus_mesh_positions(m, lod, part), want.positions, 3 * n));
  CHECK(same_bytes(ramus_mesh_normals(m, lod, part), want.normals, 3 * n));
  CHECK(same_bytes(ramus_mesh_uvs(m, lod, part), want.uvs, 2 * n));
  CHECK(same_bytes(ramus_mesh_wind(m, lod, part), want.wind, 4 * n));
  CHECK(same_bytes(ramus_mesh_skin_nodes(m, lod, part), want.skin_node, n));
  CHECK(same_bytes(ramus_mesh_indices(m, lod, part), want.indices, want.indices.size()));
  CHECK((ramus_mesh_tangents(m, lod, part) != nullptr) == (part == RAMUS_PART_BARK));
}

}  // namespace

TEST_CASE("mesher: z-up arrays are build_tree_lods' for the same options", "[runtime]") {
  const std::string example =
      GENERATE(as<std::string>{}, "trees/broadleaf.ramus", "abop/fig1_25.ramus",
               "abop/fig5_5_cordate_leaf.ramus", "abop/fig2_8a_ternary.ramus");
  INFO(example);
  const Grown g = grow_both(example);
  ramus_mesh_options o;
  ramus_mesh_options_init(&o);
  o.y_up = 0;
  o.lod_count = 3;
  o.crossed_leaves = 1;
  o.leaf_scale = 0.75;
  o.pipe_exponent = example == "abop/fig2_8a_ternary.ramus" ? 2.5 : 0;
  char err[256] = "unset";
  MeshPtr m(ramus_mesh_build(g.skeleton.get(), &o, err, sizeof err), ramus_free_mesh);
  INFO(err);
  REQUIRE(m);
  CHECK(std::string(err).empty());
  ramus::mesh::MeshOptions mo;
  mo.lod_count = 3;
  mo.leaf_style = ramus::mesh::LeafStyle::kCrossed;
  mo.leaf_scale = 0.75;
  mo.pipe_exponent = o.pipe_exponent;
  const std::vector<ramus::mesh::TreeMesh> want = ramus::mesh::build_tree_lods(g.source, mo);
  REQUIRE(ramus_mesh_lod_count(m.get()) == 3);
  for (int lod = 0; lod < 3; ++lod) {
    require_part(m.get(), lod, RAMUS_PART_BARK, want[lod].bark);
    require_part(m.get(), lod, RAMUS_PART_LEAVES, want[lod].leaves);
    require_part(m.get(), lod, RAMUS_PART_SURFACES, want[lod].surfaces);
  }
  double origin[3] = {7, 7, 7};
  CHECK(ramus_mesh_origin(m.get(), origin) == 0);
  CHECK((origin[0] == 0 && origin[1] == 0 && origin[2] == 0));
}

TEST_CASE("mesher: frames, orders and organ nodes are the skeleton's", "[runtime]") {
  const Grown g = grow_both("trees/broadleaf.ramus");
  const ramus_skeleton* s = g.skeleton.get();
  REQUIRE(ramus_node_count(s) == g.source.nodes.size());
  REQUIRE(ramus_organ_count(s) == g.source.organs.size());
  auto same = [](const double* got, const ramus::Vec3& want) {
    return std::memcmp(got, &want.x, sizeof(double)) == 0 &&
           std::memcmp(got + 1, &want.y, sizeof(double)) == 0 &&
           std::memcmp(got + 2, &want.z, sizeof(double)) == 0;
  };
  bool lateral = false;
  for (std::size_t i = 0; i < g.source.nodes.size(); ++i) {
    const ramus::SkeletonNode& n = g.source.nodes[i];
    double h[3], l[3], u[3];
    REQUIRE(ramus_node_frame(s, i, h, l, u) == 0);
    REQUIRE((same(h, n.heading) && same(l, n.left) && same(u, n.up)));
    REQUIRE(ramus_node_order(s, i) == n.order);
    lateral = lateral || n.order > 0;
  }
  CHECK(lateral);
  for (std::size_t i = 0; i < g.source.organs.size(); ++i) {
    const ramus::OrganAnchor& o = g.source.organs[i];
    double h[3], l[3], u[3];
    REQUIRE(ramus_organ_frame(s, i, h, l, u) == 0);
    REQUIRE((same(h, o.heading) && same(l, o.left) && same(u, o.up)));
    REQUIRE(ramus_organ_node(s, i) == (o.node == ramus::kNoParent ? -1 : std::int64_t(o.node)));
  }
  double h[3] = {7, 7, 7};
  CHECK(ramus_node_frame(s, g.source.nodes.size(), h, nullptr, nullptr) == -1);
  CHECK(h[0] == 7);
  CHECK(ramus_node_frame(s, 0, h, nullptr, nullptr) == 0);  // each output may be NULL
  CHECK(ramus_node_order(s, g.source.nodes.size()) == -1);
  CHECK(ramus_organ_frame(s, g.source.organs.size(), h, h, h) == -1);
  CHECK(ramus_organ_node(s, g.source.organs.size()) == -1);
  CHECK(ramus_node_order(nullptr, 0) == -1);
}

TEST_CASE("mesher: invalid options and arguments are errors, not crashes", "[runtime]") {
  const Grown g = grow_both("abop/fig1_24a.ramus");
  char err[256];
  ramus_mesh_options o;
  auto fails_with = [&](const char* words) {
    std::strcpy(err, "unset");
    MeshPtr m(ramus_mesh_build(g.skeleton.get(), &o, err, sizeof err), ramus_free_mesh);
    INFO(err);
    CHECK(m == nullptr);
    CHECK(std::string(err).find(words) != std::string::npos);
  };
  ramus_mesh_options_init(&o);
  o.lod_count = 0;
  fails_with("LOD count must be 1..8");
  o.lod_count = 9;
  fails_with("LOD count must be 1..8");
  ramus_mesh_options_init(&o);
  o.leaf_scale = 0;
  fails_with("leaf scale must be > 0");
  ramus_mesh_options_init(&o);
  o.pipe_exponent = 0.5;
  fails_with("pipe exponent must be at least 1");
  ramus_mesh_options_init(&o);
  o.crossed_leaves = 2;
  fails_with("crossed_leaves must be 0 or 1");
  ramus_mesh_options_init(&o);
  o.y_up = -1;
  fails_with("y_up must be 0 or 1");
  CHECK(ramus_mesh_build(nullptr, nullptr, err, sizeof err) == nullptr);
  CHECK(std::string(err).find("null skeleton") != std::string::npos);

  MeshPtr m(ramus_mesh_build(g.skeleton.get(), nullptr, nullptr, 0), ramus_free_mesh);
  REQUIRE(m);  // NULL options: the defaults, one level
  CHECK(ramus_mesh_lod_count(m.get()) == 1);
  CHECK(ramus_mesh_vertex_count(m.get(), 0, RAMUS_PART_BARK) > 0);
  for (auto [lod, part] : {std::pair{1, 0}, {-1, 0}, {0, 3}, {0, -1}}) {
    CHECK(ramus_mesh_vertex_count(m.get(), lod, part) == 0);
    CHECK(ramus_mesh_index_count(m.get(), lod, part) == 0);
    CHECK(ramus_mesh_positions(m.get(), lod, part) == nullptr);
    CHECK(ramus_mesh_indices(m.get(), lod, part) == nullptr);
  }
  CHECK(ramus_mesh_tangents(m.get(), 0, RAMUS_PART_LEAVES) == nullptr);
  CHECK(ramus_mesh_lod_count(nullptr) == 0);
  CHECK(ramus_mesh_positions(nullptr, 0, 0) == nullptr);
  double xyz[3];
  CHECK(ramus_mesh_origin(nullptr, xyz) == -1);
  ramus_mesh_options_init(nullptr);  // no crash
  ramus_free_mesh(nullptr);
}
