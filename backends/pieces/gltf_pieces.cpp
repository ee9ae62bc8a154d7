// glTF encodings of a pieces forest (gltf_pieces.h). The second file that includes tiny_gltf.h
// (after backends/mesh/gltf_writer.cpp); the validator rules it follows are the same: views on
// 4-byte boundaries, vertex views with the ARRAY_BUFFER target, index views ELEMENT_ARRAY_BUFFER,
// inverse bind matrices, animation and instance data in views without a target or stride, exact
// min/max on every float vertex accessor, and skin weights that sum to one in float.
// glTF is y up; the pieces are assembled in ramus's z-up world. Every position, normal, rotation
// and matrix is turned as it enters the model (y_up, y_up_quat, matrices: through
// core/up_axis.h): vertices and points turn by R, transforms are conjugated R M R^-1,
// so skinning, instancing and the wind clip give the z-up result turned by R.
#include "backends/pieces/gltf_pieces.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <span>
#include <sstream>

#include "backends/mesh/gltf_buffer_builder.h"
#include "backends/mesh/leaf_shape.h"
#include "backends/pieces/bark_tiles.h"
#include "backends/pieces/foliage.h"
#include "backends/pieces/skin_vertex.h"
#include "backends/texture/bark_maps.h"
#include "core/up_axis.h"
#include "mesh/tangents.h"

namespace ramus::pieces {
namespace {

using tinygltf::Value;

std::string node_safe(const std::string& s) {
  std::string out;
  for (unsigned char c : s) out += std::isalnum(c) ? char(c) : '_';
  return out;
}

// A rotation of the z-up world as glTF's y-up (x, y, z, w), normalized.
std::array<double, 4> y_up_quat(const Quat& q) {
  const Quat n = q.normalized();
  return mesh::z_up_to_y_up_quaternion(n.x, n.y, n.z, n.w);
}

std::array<float, 4> unit_quat(const Quat& q) {
  const std::array<double, 4> n = y_up_quat(q);
  return {float(n[0]), float(n[1]), float(n[2]), float(n[3])};
}

Vec3 y_up(const Vec3& v) { return mesh::z_up_to_y_up(v); }

const texture::TileAtlas& atlas_of(const PiecesGltfOptions& o) {
  return o.bark ? *o.bark : texture::bundled_bark_atlas();
}

class Builder : public mesh::GltfBufferBuilder {
 public:
  int view(const void* data, std::size_t bytes, int target) {
    return add_view(data, bytes, target);
  }

  int accessor(int view, int component, std::size_t count, int type, bool normalized = false,
               std::vector<double> lo = {}, std::vector<double> hi = {}) {
    return add_accessor(view, component, count, type, std::move(lo), std::move(hi), normalized);
  }

  // Float data of `comps` components per element; with_bounds adds exact min/max.
  int floats(const std::vector<float>& f, int comps, int type, int target, bool with_bounds) {
    return add_floats(f.data(), f.size() / comps, comps, type, target, with_bounds);
  }

  int joints(const std::vector<std::uint32_t>& j, bool wide) {
    if (wide) {
      std::vector<std::uint16_t> s(j.begin(), j.end());
      const int v = view(s.data(), s.size() * 2, TINYGLTF_TARGET_ARRAY_BUFFER);
      return accessor(v, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, s.size() / 4, TINYGLTF_TYPE_VEC4);
    }
    std::vector<std::uint8_t> s(j.begin(), j.end());
    const int v = view(s.data(), s.size(), TINYGLTF_TARGET_ARRAY_BUFFER);
    return accessor(v, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, s.size() / 4, TINYGLTF_TYPE_VEC4);
  }

  // Transforms of the z-up world (inverse bind and skinning matrices), conjugated into y up.
  int matrices(const std::vector<Mat4>& ms) {
    std::vector<float> f;
    f.reserve(ms.size() * 16);
    for (const Mat4& m : ms)
      for (double x : mesh::z_up_to_y_up_matrix(m.m)) f.push_back(float(x));
    return floats(f, 16, TINYGLTF_TYPE_MAT4, 0, false);
  }

  // The bark: the tile set's padded atlas (docs/textures.md), one tile per quad.
  int material(const PiecesGltfOptions& o) {
    tinygltf::Material m;
    m.name = "bark";
    const texture::BarkTextures bark =
        o.bark ? texture::bark_atlas_textures(*o.bark) : texture::bundled_bark_atlas_textures();
    m.pbrMetallicRoughness.baseColorTexture.index =
        add_texture(bark.base, "bark", TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE, bark.mime);
    m.normalTexture.index =
        add_texture(bark.normal, "bark_normal", TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE, bark.mime);
    m.pbrMetallicRoughness.metallicFactor = 0.0;
    m.pbrMetallicRoughness.roughnessFactor = 0.9;
    model_.materials.push_back(m);
    return int(model_.materials.size() - 1);
  }

  // The leaves: the mesh builds' leaf picture, alpha-tested; the cards are one-faced, so the
  // material is double-sided.
  int leaf_material() {
    tinygltf::Material m;
    m.name = "leaf";
    m.pbrMetallicRoughness.baseColorTexture.index =
        add_texture(mesh::leaf_texture_png(512, 1024), "leaf", TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE);
    m.pbrMetallicRoughness.metallicFactor = 0.0;
    m.pbrMetallicRoughness.roughnessFactor = 0.8;
    m.alphaMode = "MASK";
    m.alphaCutoff = 0.5;
    m.doubleSided = true;
    model_.materials.push_back(m);
    return int(model_.materials.size() - 1);
  }
};

Value int_array(const std::vector<std::uint16_t>& v, std::size_t first, std::size_t count) {
  Value::Array a;
  a.reserve(count);
  for (std::size_t i = 0; i < count; ++i) a.emplace_back(int(v[first + i]));
  return Value(std::move(a));
}

// Triangles of the quads written corner by corner from `base` (quad q's corners are vertices
// base + 4q .. base + 4q + 3): quad q becomes triangles 2q (a b c) and 2q + 1 (a c d).
void append_triangles(const PieceMesh& mesh, std::uint32_t base, std::vector<std::uint32_t>& out) {
  for (std::uint32_t q = 0; q < mesh.quads.size(); ++q) {
    for (int k : {0, 1, 2, 0, 2, 3}) out.push_back(base + 4 * q + std::uint32_t(k));
  }
}

const PieceMesh& lod_mesh(const PieceSet& set, std::uint32_t type, std::size_t lod) {
  const PieceType& t = set.types[type];
  if (lod >= t.lods.size()) {
    throw PiecesError("piece " + t.name + " has " + std::to_string(t.lods.size()) +
                      " levels of detail; level " + std::to_string(lod) + " was asked for");
  }
  return t.lods[lod];
}

// POSITION, NORMAL and TEXCOORD_0 of a triangle primitive, in that accessor order (bark pieces
// and leaf cards alike).
void add_surface_attributes(Builder& b, tinygltf::Primitive& prim, const std::vector<float>& pos,
                            const std::vector<float>& nrm, const std::vector<float>& uv) {
  prim.attributes["POSITION"] =
      b.floats(pos, 3, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER, true);
  prim.attributes["NORMAL"] =
      b.floats(nrm, 3, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER, true);
  prim.attributes["TEXCOORD_0"] =
      b.floats(uv, 2, TINYGLTF_TYPE_VEC2, TINYGLTF_TARGET_ARRAY_BUFFER, true);
}

// Vertex attributes of one primitive, filled piece by piece.
struct SkinnedVertices {
  std::vector<float> pos, nrm, uv, wts;
  std::vector<std::uint32_t> jts, idx;

  std::uint32_t size() const { return std::uint32_t(pos.size() / 3); }

  // Appends vertex v of `m` at `position` with `normal`, its joints offset by `bone_offset`.
  void add(const PieceMesh& m, std::size_t v, const Vec3& position, const Vec3& normal,
           std::uint32_t bone_offset) {
    const Vec3 p = y_up(position);
    for (int c = 0; c < 3; ++c) pos.push_back(float(p[c]));
    const Vec3 n = y_up(normalized(normal));
    for (int c = 0; c < 3; ++c) nrm.push_back(float(n[c]));
    const SkinVertex s = normalize_skin(m.joints.at(v), m.weights.at(v), bone_offset);
    jts.insert(jts.end(), s.joints.begin(), s.joints.end());
    wts.insert(wts.end(), s.weights.begin(), s.weights.end());
  }

  // The triangle primitive: JOINTS_0/WEIGHTS_0 when `skinned`, otherwise the custom
  // _JOINTS_0/_WEIGHTS_0 for instancing shaders (whose weights then carry bounds, as every
  // non-skin float attribute must).
  tinygltf::Primitive primitive(Builder& b, int material, bool wide_joints, bool skinned) const {
    tinygltf::Primitive prim;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    prim.material = material;
    add_surface_attributes(b, prim, pos, nrm, uv);
    // The bark material's normal map needs tangents (mesh/tangents.h).
    prim.attributes["TANGENT"] = b.floats(mesh::vertex_tangents(pos, nrm, uv, idx), 4,
                                          TINYGLTF_TYPE_VEC4, TINYGLTF_TARGET_ARRAY_BUFFER, true);
    prim.attributes[skinned ? "JOINTS_0" : "_JOINTS_0"] = b.joints(jts, wide_joints);
    prim.attributes[skinned ? "WEIGHTS_0" : "_WEIGHTS_0"] =
        b.floats(wts, 4, TINYGLTF_TYPE_VEC4, TINYGLTF_TARGET_ARRAY_BUFFER, !skinned);
    prim.indices = b.add_indices(idx, size());
    return prim;
  }
};

// A piece type's mesh in piece space, its bark showing `tiles`; `skinned` adds JOINTS_0/WEIGHTS_0
// (piece-local joints), otherwise the same binding goes into the custom _JOINTS_0/_WEIGHTS_0 for
// instancing shaders. Every quad has its own four corners (the tiles differ from quad to quad).
int add_piece_mesh(Builder& b, const PieceSet& set, std::uint32_t type, std::size_t lod,
                   int material, bool skinned, std::span<const std::uint16_t> tiles,
                   const texture::TileAtlas& atlas) {
  const PieceMesh& m = lod_mesh(set, type, lod);
  SkinnedVertices sv;
  for (const auto& q : m.quads) {
    for (std::uint32_t v : q) sv.add(m, v, m.positions[v], m.normals.at(v), 0);
  }
  sv.uv = bark_uvs(m, tiles, atlas);
  append_triangles(m, 0, sv.idx);
  const bool wide = set.types[type].joints.size() > 255;
  const tinygltf::Primitive prim = sv.primitive(b, material, wide, skinned);
  tinygltf::Mesh mesh;
  mesh.name = set.types[type].name;
  mesh.primitives.push_back(prim);
  Value::Object extras;
  extras["pieceType"] = Value(set.types[type].name);
  extras["segments"] = Value(m.segments);
  extras["quads"] = Value(int(m.quads.size()));
  if (m.segments > 1) {
    Value::Array src;
    for (std::uint32_t s : m.quad_source) src.emplace_back(int(s));
    extras["quadSource"] = Value(std::move(src));
  }
  mesh.extras = Value(std::move(extras));
  b.model().meshes.push_back(std::move(mesh));
  return int(b.model().meshes.size() - 1);
}

// Node 0 is the root of the bone hierarchies; bone g (global) is node 1 + g.
void add_bone_nodes(Builder& b, const Forest& forest, const PiecesLayout& layout,
                    const PieceSet& set, const std::string& name) {
  auto& nodes = b.model().nodes;
  tinygltf::Node root;
  root.name = name + "_bones";
  nodes.push_back(root);
  for (std::size_t k = 0; k < forest.trees.size(); ++k) {
    const Tree& tree = forest.trees[k];
    for (std::size_t i = 0; i < tree.bones.size(); ++i) {
      const std::uint32_t g = layout.tree_bone_base[k] + std::uint32_t(i);
      const Bone& bone = tree.bones[i];
      const PlacedPiece& piece = tree.pieces[bone.piece];
      tinygltf::Node n;
      n.name = "t" + std::to_string(k) + "_p" + std::to_string(bone.piece) + "_" +
               node_safe(set.types[piece.type].joints[bone.joint].name);
      const Trs& t = layout.bone_local[g];
      const Vec3 tt = y_up(t.t);
      n.translation = {tt.x, tt.y, tt.z};
      const std::array<double, 4> q = y_up_quat(t.r);
      n.rotation = {q[0], q[1], q[2], q[3]};
      n.scale = {t.s, t.s, t.s};
      nodes.push_back(n);
      const std::uint32_t parent = layout.bone_parent[g];
      nodes[parent == kNone ? 0 : 1 + parent].children.push_back(int(1 + g));
    }
  }
}

// The wind clip of every tree as one looping animation of the bone nodes' rotations. Only bones
// whose rotation changes get a channel.
void add_wind(Builder& b, const Forest& forest, const PiecesLayout& layout,
              const PiecesGltfOptions& o) {
  tinygltf::Animation anim;
  anim.name = "wind";
  std::map<std::vector<double>, int> inputs;  // key times -> accessor
  for (std::size_t k = 0; k < forest.trees.size(); ++k) {
    const Tree& tree = forest.trees[k];
    WindOptions wo = o.wind_options;
    wo.seed = o.wind_options.seed + k;
    const WindClip clip = wind_clip(tree, tree.pose, wo);
    if (clip.times.size() < 2) continue;
    auto [it, fresh] = inputs.try_emplace(clip.times, -1);
    for (std::size_t bone = 0; bone < tree.bones.size(); ++bone) {
      bool moves = false;
      const Quat& q0 = clip.rotations.at(0).at(bone);
      for (const auto& key : clip.rotations) {
        const Quat& q = key.at(bone);
        moves = moves || std::abs(q.w - q0.w) + std::abs(q.x - q0.x) + std::abs(q.y - q0.y) +
                                 std::abs(q.z - q0.z) >
                             1e-9;
      }
      if (!moves) continue;
      if (it->second < 0) {
        std::vector<float> t(clip.times.begin(), clip.times.end());
        it->second = b.floats(t, 1, TINYGLTF_TYPE_SCALAR, 0, true);
      }
      std::vector<float> out;
      for (const auto& key : clip.rotations) {
        const auto q = unit_quat(key[bone]);
        out.insert(out.end(), q.begin(), q.end());
      }
      tinygltf::AnimationSampler s;
      s.input = it->second;
      s.output = b.floats(out, 4, TINYGLTF_TYPE_VEC4, 0, false);
      s.interpolation = "LINEAR";
      anim.samplers.push_back(s);
      tinygltf::AnimationChannel c;
      c.sampler = int(anim.samplers.size() - 1);
      c.target_node = int(1 + layout.tree_bone_base[k] + bone);
      c.target_path = "rotation";
      anim.channels.push_back(c);
    }
  }
  if (!anim.channels.empty()) b.model().animations.push_back(std::move(anim));
}

// The bark tiles of every tree (bark_tiles.h), seeded per tree.
std::vector<BarkTiling> forest_bark(const PieceSet& set, const Forest& forest,
                                    const PiecesGltfOptions& o) {
  std::vector<BarkTiling> out;
  for (std::size_t k = 0; k < forest.trees.size(); ++k) {
    out.push_back(bark_tiling(set, forest.trees[k], atlas_of(o).edges, o.seed + k));
  }
  return out;
}

Value json_vec3(const Vec3& v) { return Value(Value::Array{Value(v.x), Value(v.y), Value(v.z)}); }

// The leaf cards of every tree's foliage clouds (foliage.h) as one primitive: skinned to the
// clouds' bones (a skin of those bone nodes), or fixed in the world when there are no bone
// nodes (gpu-instancing). Returns the node, or -1 when no tree has an open leaf rim; `clouds`
// gets each cloud's centre and radius (glTF's y-up world) for the foliage extras.
int add_leaves(Builder& b, const PieceSet& set, const Forest& forest, const PiecesLayout& layout,
               const PiecesGltfOptions& o, bool skinned, Value::Array& clouds) {
  const std::vector<FoliageCloud> all = forest_clouds(set, forest, layout);
  if (all.empty()) return -1;
  for (const FoliageCloud& c : all) {
    Value::Object cloud;
    cloud["centre"] = json_vec3(y_up(c.centre));
    cloud["radius"] = Value(c.radius);
    clouds.emplace_back(std::move(cloud));
  }
  const LeafCards cards = leaf_cards(all, o.seed);
  std::map<std::uint32_t, std::uint32_t> joint_of;  // global bone -> skin joint
  for (std::uint32_t bone : cards.bones) joint_of.try_emplace(bone, 0);
  std::vector<std::uint32_t> joint_bones;
  for (auto& [bone, j] : joint_of) {
    j = std::uint32_t(joint_bones.size());
    joint_bones.push_back(bone);
  }
  std::vector<float> pos, nrm, uv, wts;
  std::vector<std::uint32_t> jts;
  for (std::size_t v = 0; v < cards.positions.size(); ++v) {
    const Vec3 p = y_up(cards.positions[v]), n = y_up(cards.normals[v]);
    pos.insert(pos.end(), {float(p.x), float(p.y), float(p.z)});
    nrm.insert(nrm.end(), {float(n.x), float(n.y), float(n.z)});
    uv.insert(uv.end(), cards.uvs[v].begin(), cards.uvs[v].end());
    jts.insert(jts.end(), {joint_of[cards.bones[v]], 0, 0, 0});
    wts.insert(wts.end(), {1, 0, 0, 0});
  }
  tinygltf::Primitive prim;
  prim.mode = TINYGLTF_MODE_TRIANGLES;
  prim.material = b.leaf_material();
  add_surface_attributes(b, prim, pos, nrm, uv);
  if (skinned) {
    prim.attributes["JOINTS_0"] = b.joints(jts, joint_bones.size() > 255);
    prim.attributes["WEIGHTS_0"] =
        b.floats(wts, 4, TINYGLTF_TYPE_VEC4, TINYGLTF_TARGET_ARRAY_BUFFER, false);
  }
  prim.indices = b.add_indices(cards.indices, std::uint32_t(cards.positions.size()));
  auto& model = b.model();
  tinygltf::Mesh mesh;
  mesh.name = o.name + "_leaves";
  mesh.primitives.push_back(prim);
  model.meshes.push_back(std::move(mesh));
  tinygltf::Node n;
  n.name = o.name + "_leaves";
  n.mesh = int(model.meshes.size() - 1);
  if (skinned) {
    tinygltf::Skin skin;
    skin.name = o.name + "_leaves";
    std::vector<Mat4> ibm;
    for (std::uint32_t g : joint_bones) {
      skin.joints.push_back(int(1 + g));
      ibm.push_back(layout.bone_world[g].inverse().matrix());
    }
    skin.inverseBindMatrices = b.matrices(ibm);
    model.skins.push_back(skin);
    n.skin = int(model.skins.size() - 1);
  }
  model.nodes.push_back(n);
  return int(model.nodes.size() - 1);
}

// {"ramus_foliage": {"clouds": [...]}} (docs/textures.md), the extras of the scene's first node.
Value foliage_extras(Value::Array clouds) {
  Value::Object foliage, extras;
  foliage["clouds"] = Value(std::move(clouds));
  extras["ramus_foliage"] = Value(std::move(foliage));
  return Value(std::move(extras));
}

Value scene_extras(const PieceSet& set, const Forest& forest, const PiecesLayout& layout,
                   const char* encoding) {
  Value::Object e;
  e["pieceSet"] = Value(set.name);
  e["encoding"] = Value(std::string(encoding));
  e["trees"] = Value(int(forest.trees.size()));
  e["pieces"] = Value(int(layout.instances.size()));
  e["bones"] = Value(int(layout.bone_count()));
  return Value(std::move(e));
}

void build_canonical(Builder& b, const PieceSet& set, const Forest& forest,
                     const PiecesLayout& layout, const PiecesGltfOptions& o) {
  const int material = b.material(o);
  const std::vector<BarkTiling> bark = forest_bark(set, forest, o);
  std::vector<int> ibm_of(set.types.size(), -1);
  for (std::uint32_t t = 0; t < set.types.size(); ++t) {
    if (layout.type_ranges[t].count == 0) continue;
    std::vector<Mat4> ibm;
    for (const Joint& j : set.types[t].joints) ibm.push_back(j.inverse_bind);
    ibm_of[t] = b.matrices(ibm);
  }
  add_bone_nodes(b, forest, layout, set, o.name);
  auto& model = b.model();
  tinygltf::Scene scene;
  scene.name = o.name;
  scene.nodes.push_back(0);
  // A mesh per piece type and tile choice: the instances' meshes share every accessor but the
  // texture coordinates (one skin per instance either way).
  std::vector<int> first_mesh(set.types.size(), -1);
  std::map<std::pair<std::uint32_t, std::vector<std::uint16_t>>, int> mesh_of;
  for (const OutputInstance& inst : layout.instances) {
    const PieceType& type = set.types[inst.type];
    const std::vector<std::uint16_t>& tiles = bark[inst.tree].tiles[inst.piece];
    auto [it, fresh] = mesh_of.try_emplace({inst.type, tiles}, -1);
    if (fresh && first_mesh[inst.type] < 0) {
      it->second = first_mesh[inst.type] =
          add_piece_mesh(b, set, inst.type, o.lod, material, true, tiles, atlas_of(o));
    } else if (fresh) {
      tinygltf::Mesh copy = model.meshes[first_mesh[inst.type]];
      copy.primitives[0].attributes["TEXCOORD_0"] =
          b.floats(bark_uvs(lod_mesh(set, inst.type, o.lod), tiles, atlas_of(o)), 2,
                   TINYGLTF_TYPE_VEC2, TINYGLTF_TARGET_ARRAY_BUFFER, true);
      model.meshes.push_back(std::move(copy));
      it->second = int(model.meshes.size() - 1);
    }
    tinygltf::Skin skin;
    skin.name = "t" + std::to_string(inst.tree) + "_p" + std::to_string(inst.piece);
    skin.inverseBindMatrices = ibm_of[inst.type];
    skin.skeleton = int(1 + inst.bone_offset);
    for (std::size_t j = 0; j < type.joints.size(); ++j)
      skin.joints.push_back(int(1 + inst.bone_offset + j));
    model.skins.push_back(skin);
    tinygltf::Node n;
    n.name = skin.name + "_" + node_safe(type.name);
    n.mesh = it->second;
    n.skin = int(model.skins.size() - 1);
    Value::Object extras;
    extras["tree"] = Value(int(inst.tree));
    extras["piece"] = Value(int(inst.piece));
    extras["pieceType"] = Value(type.name);
    extras["boneOffset"] = Value(int(inst.bone_offset));
    extras["tiles"] = int_array(layout.tiles, inst.tile_offset, inst.tile_count);
    extras["barkTiles"] = int_array(tiles, 0, tiles.size());
    n.extras = Value(std::move(extras));
    model.nodes.push_back(n);
    scene.nodes.push_back(int(model.nodes.size() - 1));
  }
  Value::Array clouds;
  const int leaves = add_leaves(b, set, forest, layout, o, true, clouds);
  if (leaves >= 0) {
    scene.nodes.push_back(leaves);
    model.nodes[0].extras = foliage_extras(std::move(clouds));
  }
  if (o.wind) add_wind(b, forest, layout, o);
  scene.extras = scene_extras(set, forest, layout, "canonical");
  model.scenes.push_back(scene);
  model.defaultScene = 0;
}

void build_flattened(Builder& b, const PieceSet& set, const Forest& forest,
                     const PiecesLayout& layout, const PiecesGltfOptions& o) {
  if (layout.bone_count() > 0xffff) {
    throw PiecesError("--flatten addresses bones with 16-bit joint indices; this forest has " +
                      std::to_string(layout.bone_count()) + " bones (use fewer trees or " +
                      "the canonical encoding)");
  }
  const int material = b.material(o);
  // The bind pose of the merged mesh is the written pose: vertices are the skinned positions,
  // each bone's inverse bind matrix the inverse of its world transform.
  std::vector<Mat4> world(layout.bone_count()), ibm(layout.bone_count());
  for (std::size_t g = 0; g < world.size(); ++g) {
    world[g] = layout.bone_world[g].matrix();
    ibm[g] = layout.bone_world[g].inverse().matrix();
  }
  const std::vector<BarkTiling> bark = forest_bark(set, forest, o);
  SkinnedVertices sv;
  Value::Array pieces;
  std::size_t first_quad = 0;
  for (const OutputInstance& inst : layout.instances) {
    const Tree& tree = forest.trees[inst.tree];
    const PieceMesh& m = lod_mesh(set, inst.type, o.lod);
    const std::span<const Mat4> tree_world(world.data() + layout.tree_bone_base[inst.tree],
                                           tree.bones.size());
    const SkinnedPiece sp = skin_piece(set, tree, tree_world, inst.piece, o.lod);
    const std::uint32_t base = sv.size();
    for (const auto& q : m.quads) {
      for (std::uint32_t v : q) sv.add(m, v, sp.positions[v], sp.normals[v], inst.bone_offset);
    }
    const std::vector<std::uint16_t>& tiles = bark[inst.tree].tiles[inst.piece];
    const std::vector<float> uv = bark_uvs(m, tiles, atlas_of(o));
    sv.uv.insert(sv.uv.end(), uv.begin(), uv.end());
    append_triangles(m, base, sv.idx);
    Value::Object p;
    p["tree"] = Value(int(inst.tree));
    p["piece"] = Value(int(inst.piece));
    p["pieceType"] = Value(set.types[inst.type].name);
    p["boneOffset"] = Value(int(inst.bone_offset));
    p["firstQuad"] = Value(int(first_quad));
    p["quads"] = Value(int(m.quads.size()));
    p["tiles"] = int_array(layout.tiles, inst.tile_offset, inst.tile_count);
    p["barkTiles"] = int_array(tiles, 0, tiles.size());
    pieces.emplace_back(std::move(p));
    first_quad += m.quads.size();
  }
  if (sv.idx.empty()) throw PiecesError("nothing to write: the forest has no geometry");
  const tinygltf::Primitive prim = sv.primitive(b, material, true, true);
  auto& model = b.model();
  tinygltf::Mesh mesh;
  mesh.name = o.name;
  mesh.primitives.push_back(prim);
  model.meshes.push_back(std::move(mesh));
  add_bone_nodes(b, forest, layout, set, o.name);
  tinygltf::Skin skin;
  skin.name = o.name;
  skin.inverseBindMatrices = b.matrices(ibm);
  skin.skeleton = 0;
  for (std::size_t g = 0; g < layout.bone_count(); ++g) skin.joints.push_back(int(1 + g));
  model.skins.push_back(skin);
  tinygltf::Node n;
  n.name = o.name + "_mesh";
  n.mesh = 0;
  n.skin = 0;
  Value::Object extras;
  extras["pieces"] = Value(std::move(pieces));
  n.extras = Value(std::move(extras));
  model.nodes.push_back(n);
  tinygltf::Scene scene;
  scene.name = o.name;
  scene.nodes = {0, int(model.nodes.size() - 1)};
  Value::Array clouds;
  const int leaves = add_leaves(b, set, forest, layout, o, true, clouds);
  if (leaves >= 0) {
    scene.nodes.push_back(leaves);
    model.nodes[0].extras = foliage_extras(std::move(clouds));
  }
  if (o.wind) add_wind(b, forest, layout, o);
  scene.extras = scene_extras(set, forest, layout, "flatten");
  model.scenes.push_back(scene);
  model.defaultScene = 0;
}

void build_instanced(Builder& b, const PieceSet& set, const Forest& forest,
                     const PiecesLayout& layout, const PiecesGltfOptions& o) {
  const int material = b.material(o);
  auto& model = b.model();
  model.extensionsUsed.push_back("EXT_mesh_gpu_instancing");
  tinygltf::Scene scene;
  scene.name = o.name;
  // Without skins the leaves stand still in the written pose; they come first, carrying the
  // foliage extras.
  Value::Array clouds;
  const int leaves = add_leaves(b, set, forest, layout, o, false, clouds);
  if (leaves >= 0) {
    scene.nodes.push_back(leaves);
    model.nodes[leaves].extras = foliage_extras(std::move(clouds));
  }
  for (std::uint32_t t = 0; t < set.types.size(); ++t) {
    const TypeRange r = layout.type_ranges[t];
    if (r.count == 0) continue;
    // Every instance draws one mesh: all quads show tile 0, whose four edges share colour 0, so
    // it joins itself; an engine's shader reads the per-quad tiles from the tile table.
    const std::vector<std::uint16_t> tile0(set.types[t].lods[0].quads.size(), 0);
    const int mesh = add_piece_mesh(b, set, t, o.lod, material, false, tile0, atlas_of(o));
    std::vector<float> tr, rot, scl, bone_offset, tile;
    std::vector<std::uint16_t> table;
    for (std::uint32_t i = r.first; i < r.first + r.count; ++i) {
      const OutputInstance& inst = layout.instances[layout.by_type[i]];
      // The rigid placement of the piece: its root joint's world transform (bind pose identity).
      const Trs& w = layout.bone_world[inst.bone_offset];
      const Vec3 wt = y_up(w.t);
      tr.insert(tr.end(), {float(wt.x), float(wt.y), float(wt.z)});
      const auto q = unit_quat(w.r);
      rot.insert(rot.end(), q.begin(), q.end());
      scl.insert(scl.end(), {float(w.s), float(w.s), float(w.s)});
      bone_offset.push_back(float(inst.bone_offset));
      tile.push_back(float(table.size()));
      table.insert(table.end(), layout.tiles.begin() + inst.tile_offset,
                   layout.tiles.begin() + inst.tile_offset + inst.tile_count);
    }
    Value::Object attrs;
    attrs["TRANSLATION"] = Value(b.floats(tr, 3, TINYGLTF_TYPE_VEC3, 0, true));
    attrs["ROTATION"] = Value(b.floats(rot, 4, TINYGLTF_TYPE_VEC4, 0, false));
    attrs["SCALE"] = Value(b.floats(scl, 3, TINYGLTF_TYPE_VEC3, 0, false));
    attrs["_BONE_OFFSET"] = Value(b.floats(bone_offset, 1, TINYGLTF_TYPE_SCALAR, 0, false));
    attrs["_TILE"] = Value(b.floats(tile, 1, TINYGLTF_TYPE_SCALAR, 0, false));
    Value::Object ext;
    ext["attributes"] = Value(std::move(attrs));
    tinygltf::Node n;
    n.name = node_safe(set.types[t].name) + "_instances";
    n.mesh = mesh;
    n.extensions["EXT_mesh_gpu_instancing"] = Value(std::move(ext));
    int table_accessor = -1;
    if (!table.empty()) {
      const int v = b.view(table.data(), table.size() * 2, 0);
      table_accessor =
          b.accessor(v, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, table.size(), TINYGLTF_TYPE_SCALAR);
    }
    Value::Object extras;
    extras["pieceType"] = Value(set.types[t].name);
    extras["instances"] = Value(int(r.count));
    extras["tileTable"] = Value(table_accessor);
    extras["tilesPerInstance"] = Value(int(set.types[t].lods[0].quads.size()));
    n.extras = Value(std::move(extras));
    model.nodes.push_back(n);
    scene.nodes.push_back(int(model.nodes.size() - 1));
  }
  Value e = scene_extras(set, forest, layout, "gpu-instancing");
  Value::Object obj = e.Get<Value::Object>();
  obj["boneMatrices"] = Value(b.matrices(layout.skinning));
  scene.extras = Value(std::move(obj));
  model.scenes.push_back(scene);
  model.defaultScene = 0;
}

}  // namespace

PiecesGltfBytes encode_pieces_gltf(const PieceSet& set, const Forest& forest,
                                   const PiecesGltfOptions& options, bool binary,
                                   const std::string& bin_uri) {
  const PiecesLayout layout = layout_forest(set, forest);
  if (layout.instances.empty()) throw PiecesError("nothing to write: the forest has no pieces");
  Builder b;
  switch (options.encoding) {
    case GltfEncoding::kCanonical:
      build_canonical(b, set, forest, layout, options);
      break;
    case GltfEncoding::kFlatten:
      build_flattened(b, set, forest, layout, options);
      break;
    case GltfEncoding::kGpuInstancing:
      build_instanced(b, set, forest, layout, options);
      break;
  }
  if (b.model().buffers[0].data.size() > 0xfffffff0ull) {
    throw PiecesError("the pieces need a buffer larger than glTF's 4 GiB limit");
  }
  PiecesGltfBytes out;
  if (!binary) out.bin.assign(b.model().buffers[0].data.begin(), b.model().buffers[0].data.end());
  std::ostringstream glb;
  tinygltf::TinyGLTF gltf;
  if (!gltf.WriteGltfSceneToStream(&b.model(), glb, false, true)) {
    throw PiecesError("glTF serialization failed");
  }
  if (binary) {
    out.main = glb.str();
    return out;
  }
  std::optional<std::string> json = mesh::gltf_json_with_buffer_uri(glb.str(), bin_uri);
  if (!json) throw PiecesError("glTF serialization produced no buffer");
  out.main = std::move(*json);
  return out;
}

void write_pieces_gltf(const PieceSet& set, const Forest& forest, const PiecesGltfOptions& options,
                       const std::string& path) {
  const bool written = mesh::write_gltf_files(path, [&](bool binary, const std::string& bin_uri) {
    return encode_pieces_gltf(set, forest, options, binary, bin_uri);
  });
  if (!written) throw PiecesError("a glTF file name must end in .glb or .gltf: " + path);
}

}  // namespace ramus::pieces
