// The glTF encodings of a pieces forest, read back: the file's own data (node TRS, skins,
// inverse bind matrices, JOINTS_0/WEIGHTS_0, instance attributes) must put every vertex where
// the back end's skinning puts it, turned from ramus's z up into glTF's y up, with the layout
// docs/pieces.md promises; every file passes the Khronos glTF-Validator.
#include <tiny_gltf.h>

#include <cstring>
#include <map>
#include <set>

#include "core/up_axis.h"
#include "backends/pieces/foliage.h"
#include "backends/pieces/gltf_pieces.h"
#include "backends/pieces/output_layout.h"
#include "backends/pieces/output_posed_mesh.h"
#include "core/atomic_file.h"
#include "tests/pieces/output_fixture.h"

using namespace ramus;
using namespace ramus::pieces;
using namespace output_test;

namespace {

tinygltf::Model load(const std::string& glb) {
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  const bool ok = loader.LoadBinaryFromMemory(&model, &err, &warn,
                                              reinterpret_cast<const unsigned char*>(glb.data()),
                                              unsigned(glb.size()));
  INFO(err);
  REQUIRE(ok);
  return model;
}

// Element `i`, component `c` of an accessor as double (float, normalized or plain integers).
double read(const tinygltf::Model& m, int accessor, std::size_t i, int c) {
  const tinygltf::Accessor& a = m.accessors.at(accessor);
  const tinygltf::BufferView& v = m.bufferViews.at(a.bufferView);
  const int comps = tinygltf::GetNumComponentsInType(a.type);
  const int size = tinygltf::GetComponentSizeInBytes(a.componentType);
  REQUIRE(v.byteStride == 0);
  const unsigned char* p =
      m.buffers[v.buffer].data.data() + v.byteOffset + a.byteOffset + (i * comps + c) * size;
  switch (a.componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      float f;
      std::memcpy(&f, p, 4);
      return f;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return *p;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      std::uint16_t u;
      std::memcpy(&u, p, 2);
      return u;
    }
    default:
      FAIL("unexpected component type " << a.componentType);
  }
  return 0;
}

Mat4 read_matrix(const tinygltf::Model& m, int accessor, std::size_t i) {
  Mat4 r;
  for (int k = 0; k < 16; ++k) r.m[k] = read(m, accessor, i, k);
  return r;
}

Mat4 node_local(const tinygltf::Node& n) {
  Trs t;
  if (n.translation.size() == 3) t.t = {n.translation[0], n.translation[1], n.translation[2]};
  if (n.rotation.size() == 4) t.r = {n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]};
  if (n.scale.size() == 3) {
    REQUIRE(n.scale[0] == n.scale[1]);
    REQUIRE(n.scale[1] == n.scale[2]);
    t.s = n.scale[0];
  }
  return t.matrix();
}

// World matrix of every node from the scene's roots.
std::vector<Mat4> node_worlds(const tinygltf::Model& m) {
  std::vector<Mat4> w(m.nodes.size());
  std::vector<bool> seen(m.nodes.size(), false);
  std::vector<std::pair<int, Mat4>> stack;
  for (int root : m.scenes.at(0).nodes) stack.push_back({root, Mat4::identity()});
  while (!stack.empty()) {
    auto [n, parent] = stack.back();
    stack.pop_back();
    REQUIRE_FALSE(seen[n]);
    seen[n] = true;
    w[n] = parent * node_local(m.nodes[n]);
    for (int c : m.nodes[n].children) stack.push_back({c, w[n]});
  }
  return w;
}

// Skinned position of vertex v of a node's mesh, from the file alone.
Vec3 skin_vertex(const tinygltf::Model& m, const std::vector<Mat4>& world, const tinygltf::Node& n,
                 std::size_t v) {
  const tinygltf::Skin& skin = m.skins.at(n.skin);
  const tinygltf::Primitive& prim = m.meshes.at(n.mesh).primitives.at(0);
  const Vec3 p{read(m, prim.attributes.at("POSITION"), v, 0),
               read(m, prim.attributes.at("POSITION"), v, 1),
               read(m, prim.attributes.at("POSITION"), v, 2)};
  Vec3 out{0, 0, 0};
  double total = 0;
  for (int s = 0; s < 4; ++s) {
    const double w = read(m, prim.attributes.at("WEIGHTS_0"), v, s);
    const int j = int(read(m, prim.attributes.at("JOINTS_0"), v, s));
    if (w == 0) {
      CHECK(j == 0);
      continue;
    }
    REQUIRE(j < int(skin.joints.size()));
    const Mat4 joint = world[skin.joints[j]] * read_matrix(m, skin.inverseBindMatrices, j);
    out += joint.point(p) * w;
    total += w;
  }
  CHECK(total == Approx(1.0).margin(1e-6));
  return out;
}

double tree_scale(const PieceSet& set) { return set.rim_radius * 10; }

// What the file should hold for a point or a transform of the z-up world.
Vec3 y_up(const Vec3& v) { return mesh::z_up_to_y_up(v); }
Mat4 y_up(const Mat4& m) { return Mat4{mesh::z_up_to_y_up_matrix(m.m)}; }

}  // namespace

TEST_CASE("canonical glTF: shared meshes, one skin per piece on its window of bone nodes",
          "[pieces][gltf]") {
  const PieceSet set = lower_set();
  const Forest f = forest(set, 7, 3);
  const PiecesLayout layout = layout_forest(set, f);
  const PiecesGltfBytes bytes = encode_pieces_gltf(set, f, {}, true);
  const tinygltf::Model m = load(bytes.main);
  const std::size_t pieces = piece_count(f), bones = bone_count(f);
  std::set<std::uint32_t> used_types;
  for (const auto& inst : layout.instances) used_types.insert(inst.type);
  // One mesh per piece type and bark tile choice, one primitive each (the draw calls per skin
  // are one), plus the leaves with their own skin.
  std::set<std::pair<int, std::vector<int>>> tile_choices;
  for (std::size_t i = 0; i < pieces; ++i) {
    const tinygltf::Value& bt = m.nodes.at(1 + bones + i).extras.Get("barkTiles");
    std::vector<int> t;
    for (int q = 0; q < int(bt.ArrayLen()); ++q) t.push_back(bt.Get(q).GetNumberAsInt());
    tile_choices.insert({m.nodes.at(1 + bones + i).mesh, t});
  }
  CHECK(m.meshes.size() == tile_choices.size() + 1);
  for (const auto& mesh : m.meshes) CHECK(mesh.primitives.size() == 1);
  CHECK(m.skins.size() == pieces + 1);
  CHECK(m.nodes.size() == 1 + bones + pieces + 1);
  CHECK(m.scenes.at(0).nodes.size() == 1 + pieces + 1);
  CHECK(m.nodes.at(1 + bones + pieces).name == "pieces_leaves");
  // The foliage clouds (one per open leaf rim, foliage.h) in the first node's extras, y up.
  const tinygltf::Value& clouds = m.nodes.at(0).extras.Get("ramus_foliage").Get("clouds");
  std::size_t expected_clouds = 0;
  for (std::size_t k = 0; k < f.trees.size(); ++k) {
    const Tree& tree = f.trees[k];
    const std::span<const Trs> tree_world(layout.bone_world.data() + layout.tree_bone_base[k],
                                          tree.bones.size());
    for (const FoliageCloud& c : foliage_clouds(set, tree, tree_world)) {
      REQUIRE(int(expected_clouds) < int(clouds.ArrayLen()));
      const tinygltf::Value& got = clouds.Get(int(expected_clouds++));
      const Vec3 want = y_up(c.centre);
      for (int i = 0; i < 3; ++i)
        CHECK(got.Get("centre").Get(i).GetNumberAsDouble() == Approx(want[i]).margin(1e-9));
      CHECK(got.Get("radius").GetNumberAsDouble() == Approx(c.radius));
    }
  }
  CHECK(expected_clouds > 0);
  CHECK(clouds.ArrayLen() == expected_clouds);
  std::map<std::uint32_t, int> ibm_of_type;
  const std::vector<Mat4> world = node_worlds(m);
  double worst = 0;
  for (std::size_t i = 0; i < pieces; ++i) {
    const OutputInstance& inst = layout.instances[i];
    const tinygltf::Node& n = m.nodes.at(1 + bones + i);
    // At the scene root, without transforms.
    CHECK(m.scenes[0].nodes[1 + i] == int(1 + bones + i));
    CHECK(n.translation.empty());
    CHECK(n.rotation.empty());
    CHECK(n.scale.empty());
    CHECK(n.matrix.empty());
    const tinygltf::Skin& skin = m.skins.at(n.skin);
    const PieceType& type = set.types[inst.type];
    REQUIRE(skin.joints.size() == type.joints.size());
    for (std::size_t j = 0; j < skin.joints.size(); ++j)
      CHECK(skin.joints[j] == int(1 + inst.bone_offset + j));
    // One inverse-bind-matrix accessor per piece type, holding its canonical bind pose.
    auto [it, fresh] = ibm_of_type.try_emplace(inst.type, skin.inverseBindMatrices);
    CHECK(it->second == skin.inverseBindMatrices);
    for (std::size_t j = 0; j < type.joints.size(); ++j) {
      const Mat4 ibm = read_matrix(m, skin.inverseBindMatrices, j);
      const Mat4 want = y_up(type.joints[j].inverse_bind);
      for (int k = 0; k < 16; ++k) CHECK(ibm.m[k] == Approx(want.m[k]).margin(1e-5));
    }
    CHECK(n.extras.Get("boneOffset").GetNumberAsInt() == int(inst.bone_offset));
    const tinygltf::Value& tiles = n.extras.Get("tiles");
    REQUIRE(tiles.ArrayLen() == inst.tile_count);
    for (std::size_t q = 0; q < inst.tile_count; ++q)
      CHECK(tiles.Get(int(q)).GetNumberAsInt() == f.trees[inst.tree].pieces[inst.piece].tiles[q]);
    // Skinning with the file's numbers lands where the back end's skinning does.
    const Tree& tree = f.trees[inst.tree];
    // Every quad is written corner by corner (its tiles differ from its neighbours').
    const SkinnedPiece expect = skin_piece(set, tree, bone_world(tree, tree.pose), inst.piece, 0);
    const PieceMesh& pm = type.lods[0];
    for (std::size_t q = 0; q < pm.quads.size(); ++q)
      for (int k = 0; k < 4; ++k)
        worst = std::max(worst, distance(skin_vertex(m, world, n, 4 * q + k),
                                         y_up(expect.positions[pm.quads[q][k]])));
  }
  CHECK(ibm_of_type.size() == used_types.size());
  CHECK(worst < 1e-4 * tree_scale(set));
  CHECK(m.extensionsUsed.empty());
}

TEST_CASE("flattened glTF: one mesh, one skin, one draw call, the same posed vertices",
          "[pieces][gltf]") {
  const PieceSet set = lower_set();
  const Forest f = forest(set, 11, 2);
  PiecesGltfOptions o;
  o.encoding = GltfEncoding::kFlatten;
  o.lod = 1;
  const tinygltf::Model m = load(encode_pieces_gltf(set, f, o, true).main);
  // The pieces' mesh and the leaves', each with its skin.
  REQUIRE(m.meshes.size() == 2);
  CHECK(m.meshes[0].primitives.size() == 1);
  REQUIRE(m.skins.size() == 2);
  CHECK(m.skins[0].joints.size() == bone_count(f));
  CHECK(m.nodes.size() == 1 + bone_count(f) + 2);
  const tinygltf::Node& n = m.nodes.at(1 + bone_count(f));
  CHECK(n.skin == 0);
  CHECK(n.mesh == 0);
  CHECK(n.extras.Get("pieces").ArrayLen() == piece_count(f));
  const mesh::TreeMesh posed = posed_forest_mesh(set, f, 1);
  const std::vector<Mat4> world = node_worlds(m);
  // Every quad corner by corner: vertex 4q + k of the file is corner k of quad q.
  std::size_t quads = 0;
  for (const Tree& t : f.trees)
    for (const PlacedPiece& p : t.pieces) quads += set.types[p.type].lods[1].quads.size();
  REQUIRE(m.accessors.at(m.meshes[0].primitives[0].attributes.at("POSITION")).count == 4 * quads);
  REQUIRE(posed.bark.indices.size() == 6 * quads);
  double worst = 0;
  for (std::size_t q = 0; q < quads; ++q) {
    for (int k = 0; k < 4; ++k) {
      // posed_forest_mesh's triangles of quad q: (a b c) (a c d).
      const std::uint32_t corner = posed.bark.indices[6 * q + (k == 3 ? 5 : std::size_t(k))];
      worst = std::max(worst, distance(skin_vertex(m, world, n, 4 * q + k),
                                       y_up(Vec3(posed.bark.positions[corner]))));
    }
  }
  CHECK(worst < 1e-4 * tree_scale(set));
}

TEST_CASE("gpu-instancing glTF: one instanced node per piece type, no skins, not required",
          "[pieces][gltf]") {
  const PieceSet set = lower_set();
  const Forest f = forest(set, 5, 4);
  const PiecesLayout layout = layout_forest(set, f);
  PiecesGltfOptions o;
  o.encoding = GltfEncoding::kGpuInstancing;
  const tinygltf::Model m = load(encode_pieces_gltf(set, f, o, true).main);
  CHECK(m.skins.empty());
  CHECK(m.extensionsUsed == std::vector<std::string>{"EXT_mesh_gpu_instancing"});
  CHECK(m.extensionsRequired.empty());
  std::size_t instances = 0;
  // The leaves come first, without a skin.
  REQUIRE(m.scenes.at(0).nodes.size() >= 1);
  CHECK(m.nodes.at(m.scenes[0].nodes[0]).name == "pieces_leaves");
  CHECK(m.nodes.at(m.scenes[0].nodes[0]).skin == -1);
  for (const tinygltf::Node& n : m.nodes) {
    if (n.name == "pieces_leaves") continue;
    REQUIRE(n.extensions.count("EXT_mesh_gpu_instancing") == 1);
    const tinygltf::Value& attrs = n.extensions.at("EXT_mesh_gpu_instancing").Get("attributes");
    const std::string type_name = n.extras.Get("pieceType").Get<std::string>();
    const std::uint32_t type = set.find(type_name);
    REQUIRE(type != kNone);
    const TypeRange r = layout.type_ranges[type];
    const int tr = attrs.Get("TRANSLATION").GetNumberAsInt();
    const int rot = attrs.Get("ROTATION").GetNumberAsInt();
    const int scl = attrs.Get("SCALE").GetNumberAsInt();
    const int off = attrs.Get("_BONE_OFFSET").GetNumberAsInt();
    const int tile = attrs.Get("_TILE").GetNumberAsInt();
    const int table = n.extras.Get("tileTable").GetNumberAsInt();
    for (int a : {tr, rot, scl, off, tile}) CHECK(m.accessors.at(a).count == r.count);
    for (std::uint32_t i = 0; i < r.count; ++i) {
      const OutputInstance& inst = layout.instances[layout.by_type[r.first + i]];
      CHECK(read(m, off, i, 0) == inst.bone_offset);
      // The instance transform is the root joint's world transform.
      Trs t;
      t.t = {read(m, tr, i, 0), read(m, tr, i, 1), read(m, tr, i, 2)};
      t.r = {read(m, rot, i, 3), read(m, rot, i, 0), read(m, rot, i, 1), read(m, rot, i, 2)};
      t.s = read(m, scl, i, 0);
      const Trs& w = layout.bone_world[inst.bone_offset];
      const Vec3 probe{0.3, -0.2, 1.0};
      CHECK(distance(t.point(y_up(probe)), y_up(w.point(probe))) < 1e-4 * tree_scale(set));
      const std::size_t first = std::size_t(read(m, tile, i, 0));
      for (std::uint32_t q = 0; q < inst.tile_count; ++q)
        CHECK(read(m, table, first + q, 0) == layout.tiles[inst.tile_offset + q]);
    }
    instances += r.count;
    CHECK(m.meshes.at(n.mesh).primitives.at(0).attributes.count("JOINTS_0") == 0);
    CHECK(m.meshes.at(n.mesh).primitives.at(0).attributes.count("_JOINTS_0") == 1);
  }
  CHECK(instances == piece_count(f));
  // The bone buffer: world x inverse bind of every bone.
  const int bones = m.scenes.at(0).extras.Get("boneMatrices").GetNumberAsInt();
  REQUIRE(m.accessors.at(bones).count == layout.bone_count());
  for (std::size_t g = 0; g < layout.bone_count(); g += 7) {
    const Mat4 b = read_matrix(m, bones, g);
    const Mat4 want = y_up(layout.skinning[g]);
    for (int k = 0; k < 16; ++k) CHECK(b.m[k] == Approx(want.m[k]).margin(1e-4));
  }
}

TEST_CASE("every pieces glTF encoding passes the Khronos validator", "[pieces][gltf]") {
  const fs::path dir = scratch("gltf");
  const PieceSet set = lower_set();
  std::vector<fs::path> files;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const Forest f = forest(set, seed, int(seed));
    for (auto [enc, name] : {std::pair{GltfEncoding::kCanonical, "canonical"},
                             std::pair{GltfEncoding::kFlatten, "flatten"},
                             std::pair{GltfEncoding::kGpuInstancing, "instanced"}}) {
      PiecesGltfOptions o;
      o.encoding = enc;
      o.lod = seed - 1;
      o.wind = enc != GltfEncoding::kGpuInstancing && seed != 2;
      const fs::path glb = dir / (std::string(name) + std::to_string(seed) + ".glb");
      write_pieces_gltf(set, f, o, glb.string());
      files.push_back(glb);
    }
  }
  const fs::path gltf = dir / "canonical text.gltf";  // a space in the name, .bin beside it
  write_pieces_gltf(set, forest(set, 4, 2), {}, gltf.string());
  files.push_back(gltf);
  std::string out;
  const int code = validate(files, out);
  INFO(out);
  CHECK(code == 0);
  CHECK(out.find("1 errors") == std::string::npos);
  std::size_t clean = 0;
  for (std::size_t at = out.find("0 errors, 0 warnings"); at != std::string::npos;
       at = out.find("0 errors, 0 warnings", at + 1))
    ++clean;
  CHECK(clean == files.size());
}

TEST_CASE("pieces glTF is byte-identical for the same input and differs with the seed",
          "[pieces][gltf]") {
  const PieceSet set = lower_set();
  for (auto enc :
       {GltfEncoding::kCanonical, GltfEncoding::kFlatten, GltfEncoding::kGpuInstancing}) {
    PiecesGltfOptions o;
    o.encoding = enc;
    o.wind = enc != GltfEncoding::kGpuInstancing;
    const auto a = encode_pieces_gltf(set, forest(set, 9, 2), o, true);
    const auto b = encode_pieces_gltf(set, forest(set, 9, 2), o, true);
    const auto c = encode_pieces_gltf(set, forest(set, 10, 2), o, true);
    CHECK(a.main == b.main);
    CHECK(a.main != c.main);
  }
}

TEST_CASE("the wind clip animates bone rotations and loops", "[pieces][gltf]") {
  const PieceSet set = lower_set();
  const Forest f = forest(set, 3, 2);
  PiecesGltfOptions o;
  o.wind = true;
  const tinygltf::Model m = load(encode_pieces_gltf(set, f, o, true).main);
  REQUIRE(m.animations.size() == 1);
  const auto& anim = m.animations[0];
  CHECK_FALSE(anim.channels.empty());
  const std::size_t bones = bone_count(f);
  for (const auto& c : anim.channels) {
    CHECK(c.target_path == "rotation");
    CHECK(c.target_node >= 1);
    CHECK(c.target_node <= int(bones));
    const auto& s = anim.samplers.at(c.sampler);
    const std::size_t keys = m.accessors.at(s.output).count;
    for (int k = 0; k < 4; ++k) CHECK(read(m, s.output, 0, k) == read(m, s.output, keys - 1, k));
  }
}

TEST_CASE("pieces glTF errors: unknown LOD, wrong extension, unwritable path", "[pieces][gltf]") {
  const PieceSet set = lower_set();
  const Forest f = forest(set, 1, 1);
  PiecesGltfOptions o;
  o.lod = 99;
  CHECK_THROWS_WITH(encode_pieces_gltf(set, f, o, true), Catch::Contains("level 99"));
  CHECK_THROWS_AS(write_pieces_gltf(set, f, {}, (scratch("gltf") / "x.fbx").string()), PiecesError);
  CHECK_THROWS_AS(write_pieces_gltf(set, f, {}, "/nonexistent-ramus-dir/out.glb"), WriteError);
  CHECK_THROWS_WITH(encode_pieces_gltf(set, Forest{}, {}, true), Catch::Contains("no pieces"));
}
