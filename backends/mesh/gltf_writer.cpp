// The only file that includes tiny_gltf.h (its implementation lives in Debian's libtinygltf).
// Every buffer view starts on a 4-byte boundary, attribute views carry the ARRAY_BUFFER target and
// index views ELEMENT_ARRAY_BUFFER, and every accessor has exact min/max (taken from the float
// values written), which is what the Khronos glTF-Validator checks. The z-up world becomes glTF's
// y up here, in add_part and place_node, through core/up_axis.h.
#include "backends/mesh/gltf_writer.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "backends/mesh/foliage_clouds.h"
#include "backends/mesh/gltf_buffer_builder.h"
#include "backends/mesh/gltf_container.h"
#include "backends/mesh/leaf_shape.h"
#include "backends/texture/bark_maps.h"
#include "core/up_axis.h"
#include "mesh/vertex_arrays.h"

namespace ramus::mesh {
namespace {

// The local origin of a georeferenced mesh as the node's translation (glTF stores it as a JSON
// double, so nothing is lost); nothing for a mesh at the world origin.
void place_node(tinygltf::Node& node, const Vec3& origin) {
  if (origin == Vec3{}) return;
  const Vec3 t = z_up_to_y_up(origin);
  node.translation = {t.x, t.y, t.z};
}

// MSFT_screencoverage of level k of n: the screen coverage below which an engine switches to the
// next coarser level. Each level halves the radial segments and the leaf count, so it is fine
// down to half the coverage of the level before; the coarsest level is never switched off (0:
// culling a distant tree is the engine's own distance rule).
double screen_coverage(int k, int n) { return k + 1 == n ? 0.0 : std::ldexp(0.5, -k); }

// The leaf clouds of LOD0 (foliage_clouds.h) as {"clouds": [{"centre": [x,y,z], "radius": r}]}
// in the scene's frame (y up, the local origin added), rounded to 0.1 mm (radii up, so every
// leaf stays inside) to keep the JSON short: issue 17's Draco size budget has little room.
tinygltf::Value foliage_extras(const TreeMesh& lod0) {
  auto tenth_mm = [](double v) { return std::round(v * 1e4) / 1e4; };
  tinygltf::Value::Array clouds;
  for (const FoliageCloud& c : foliage_clouds(lod0.leaves)) {
    const Vec3 p = z_up_to_y_up(lod0.origin + c.centre);
    tinygltf::Value::Object cloud;
    cloud["centre"] = tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(tenth_mm(p.x)),
                                                             tinygltf::Value(tenth_mm(p.y)),
                                                             tinygltf::Value(tenth_mm(p.z))});
    cloud["radius"] = tinygltf::Value(std::ceil(c.radius * 1e4) / 1e4);
    clouds.emplace_back(std::move(cloud));
  }
  tinygltf::Value::Object foliage;
  foliage["clouds"] = tinygltf::Value(std::move(clouds));
  return tinygltf::Value(std::move(foliage));
}

class ModelBuilder : public GltfBufferBuilder {
 public:
  // A float accessor over `count` elements of `comps` components each.
  template <typename T>
  int add_float_attribute(const std::vector<T>& values, int comps, int type) {
    static_assert(sizeof(T) % sizeof(float) == 0);
    return add_floats(reinterpret_cast<const float*>(values.data()), values.size(), comps, type,
                      TINYGLTF_TARGET_ARRAY_BUFFER, true);
  }

  // Bark: base colour and normal map of a tile set (docs/textures.md), repeating; leaves: the
  // alpha-masked leaf picture, 512 x 1024 so a leaf close to the camera stays sharp.
  int add_material(const std::string& name, bool leaf, const texture::BarkTextures& bark) {
    tinygltf::Material m;
    m.name = name;
    m.pbrMetallicRoughness.metallicFactor = 0.0;
    m.pbrMetallicRoughness.roughnessFactor = leaf ? 0.6 : 0.9;
    if (leaf) {
      m.pbrMetallicRoughness.baseColorTexture.index =
          add_texture(leaf_texture_png(512, 1024), "leaf", TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE);
      // Every leaf card carries a back face of its own, so the material stays single-sided.
      m.alphaMode = "MASK";
      m.alphaCutoff = 0.5;
      m.doubleSided = false;
    } else {
      m.pbrMetallicRoughness.baseColorTexture.index =
          add_texture(bark.base, "bark", TINYGLTF_TEXTURE_WRAP_REPEAT, bark.mime);
      m.normalTexture.index =
          add_texture(bark.normal, "bark_normal", TINYGLTF_TEXTURE_WRAP_REPEAT, bark.mime);
    }
    model_.materials.push_back(m);
    return int(model_.materials.size() - 1);
  }

  // JOINTS_0 and WEIGHTS_0 of the wind skin: each vertex follows its node's two joints.
  void add_skin_attributes(tinygltf::Primitive& prim, const MeshPart& part, const WindRig& rig) {
    if (part.skin_node.size() != part.vertex_count())
      throw MeshError("the wind skin needs the skeleton node of every vertex");
    const std::size_t n = part.vertex_count();
    // Weights as normalized bytes summing to exactly 255 (glTF 3.7.3.3 allows them unquantized
    // or so), a quarter of the floats' size.
    std::vector<std::uint8_t> weights(4 * n, 0);
    std::vector<std::uint16_t> joints(4 * n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      const JointBinding b = rig.binding(part.skin_node[i]);
      const int second = b.b != b.a ? int(std::lround(255.0 * b.t)) : 0;
      // A joint with zero weight must be index 0 (the validator's rule): all on b, b first.
      joints[4 * i] = std::uint16_t(second == 255 ? b.b : b.a);
      weights[4 * i] = std::uint8_t(second == 255 ? 255 : 255 - second);
      if (second > 0 && second < 255) {
        joints[4 * i + 1] = std::uint16_t(b.b);
        weights[4 * i + 1] = std::uint8_t(second);
      }
    }
    if (rig.joints.size() <= 256) {
      const std::vector<std::uint8_t> small(joints.begin(), joints.end());
      prim.attributes["JOINTS_0"] =
          add_accessor(add_view(small.data(), small.size(), TINYGLTF_TARGET_ARRAY_BUFFER),
                       TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, n, TINYGLTF_TYPE_VEC4);
    } else {
      prim.attributes["JOINTS_0"] =
          add_accessor(add_view(joints.data(), joints.size() * 2, TINYGLTF_TARGET_ARRAY_BUFFER),
                       TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, n, TINYGLTF_TYPE_VEC4);
    }
    prim.attributes["WEIGHTS_0"] =
        add_accessor(add_view(weights.data(), weights.size(), TINYGLTF_TARGET_ARRAY_BUFFER),
                     TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, n, TINYGLTF_TYPE_VEC4, {}, {}, true);
  }

  // The polygon organs: opaque, untextured leaf green (their UVs are planar, for a user's own
  // texture); each polygon has its own back face, so the material stays single-sided.
  int add_surface_material() {
    tinygltf::Material m;
    m.name = "surface";
    m.pbrMetallicRoughness.baseColorFactor = {0.275, 0.529, 0.176, 1.0};
    m.pbrMetallicRoughness.metallicFactor = 0.0;
    m.pbrMetallicRoughness.roughnessFactor = 0.6;
    model_.materials.push_back(m);
    return int(model_.materials.size() - 1);
  }

  tinygltf::Primitive add_part(const MeshPart& part, int material, const WindRig& rig,
                               bool tangents) {
    tinygltf::Primitive prim;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    prim.material = material;
    // The arrays the runtime hands out too (mesh/vertex_arrays.h); the bark's normal map needs
    // the tangents.
    const VertexArrays v = vertex_arrays(part, UpAxis::kY, tangents);
    const std::size_t n = part.vertex_count();
    prim.attributes["POSITION"] = add_floats(v.positions.data(), n, 3, TINYGLTF_TYPE_VEC3,
                                             TINYGLTF_TARGET_ARRAY_BUFFER, true);
    prim.attributes["NORMAL"] =
        add_floats(v.normals.data(), n, 3, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER, true);
    prim.attributes["TEXCOORD_0"] = add_float_attribute(part.uvs, 2, TINYGLTF_TYPE_VEC2);
    if (tangents) {
      prim.attributes["TANGENT"] = add_floats(v.tangents.data(), n, 4, TINYGLTF_TYPE_VEC4,
                                              TINYGLTF_TARGET_ARRAY_BUFFER, true);
    }
    prim.attributes["_WIND"] = add_float_attribute(part.wind, 4, TINYGLTF_TYPE_VEC4);
    if (!rig.empty()) add_skin_attributes(prim, part, rig);
    prim.indices = add_indices(part.indices, part.vertex_count());
    return prim;
  }
};

// Keys per period of the wind clip: enough for a smooth sine at two swings per period.
constexpr int kWindKeys = 32;

// The wind skin: joint nodes (the root joints, which carry the local origin, are scene roots
// beside the tree's node: Godot 3.2's importer hangs on a skinned mesh whose node is its
// joints' parent), one skin shared by every level's node, and the looping animation "wind" of
// the joints' rotations (wind_rig.h). Joints rest without rotation, so each turns about its
// axis as given. Returns the root joints.
std::vector<int> add_wind(ModelBuilder& b, const WindRig& rig, const Vec3& origin, int levels) {
  auto& model = b.model();
  std::vector<int> roots;
  const int first = int(model.nodes.size());
  std::vector<float> inverse_bind;
  tinygltf::Skin skin;
  skin.name = "wind";
  for (std::size_t j = 0; j < rig.joints.size(); ++j) {
    const WindJoint& w = rig.joints[j];
    tinygltf::Node node;
    node.name = "wind_joint_" + std::to_string(j);
    const Vec3 t = w.parent == kNoJoint ? z_up_to_y_up(origin + w.position)
                                        : z_up_to_y_up(w.position - rig.joints[w.parent].position);
    if (t != Vec3{}) node.translation = {t.x, t.y, t.z};
    model.nodes.push_back(node);
    if (w.parent == kNoJoint) {
      roots.push_back(first + int(j));
    } else {
      model.nodes[first + w.parent].children.push_back(first + int(j));
    }
    skin.joints.push_back(first + int(j));
    // The inverse of the joint's rest transform in the mesh's own frame (the root joints'
    // origin is outside it): joint * inverse bind = the origin's translation at rest.
    const Vec3f p(z_up_to_y_up(w.position));
    const float m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -p.x, -p.y, -p.z, 1};
    inverse_bind.insert(inverse_bind.end(), m, m + 16);
  }
  skin.inverseBindMatrices =
      b.add_floats(inverse_bind.data(), rig.joints.size(), 16, TINYGLTF_TYPE_MAT4, 0, false);
  model.skins.push_back(skin);
  model.nodes[0].skin = 0;
  for (int k = 1; k < levels; ++k) model.nodes[k].skin = 0;

  std::vector<float> times;
  for (int i = 0; i <= kWindKeys; ++i) times.push_back(float(rig.period * i / kWindKeys));
  const int input = b.add_floats(times.data(), times.size(), 1, TINYGLTF_TYPE_SCALAR, 0, true);
  tinygltf::Animation anim;
  anim.name = "wind";
  for (std::size_t j = 0; j < rig.joints.size(); ++j) {
    const WindJoint& w = rig.joints[j];
    if (w.amplitude == 0) continue;
    std::vector<float> q;
    for (int i = 0; i <= kWindKeys; ++i) {
      const double half = 0.5 * rig.angle(j, rig.period * i / kWindKeys);
      const Vec3 a = w.axis * std::sin(half);
      const auto r = z_up_to_y_up_quaternion(a.x, a.y, a.z, std::cos(half));
      q.insert(q.end(), {float(r[0]), float(r[1]), float(r[2]), float(r[3])});
    }
    tinygltf::AnimationSampler sampler;
    sampler.input = input;
    sampler.output = b.add_floats(q.data(), times.size(), 4, TINYGLTF_TYPE_VEC4, 0, false);
    sampler.interpolation = "LINEAR";
    anim.samplers.push_back(sampler);
    tinygltf::AnimationChannel channel;
    channel.sampler = int(anim.samplers.size() - 1);
    channel.target_node = first + int(j);
    channel.target_path = "rotation";
    anim.channels.push_back(channel);
  }
  if (!anim.channels.empty()) model.animations.push_back(anim);
  return roots;
}

void build_model(const std::vector<TreeMesh>& lods, const texture::BarkTextures* bark_textures,
                 ModelBuilder& b) {
  bool any_bark = false, any_leaves = false, any_surfaces = false;
  for (const TreeMesh& m : lods) {
    any_bark = any_bark || !m.bark.empty();
    any_leaves = any_leaves || !m.leaves.empty();
    any_surfaces = any_surfaces || !m.surfaces.empty();
  }
  if (!any_bark && !any_leaves && !any_surfaces) {
    throw MeshError("nothing to write: the tree has no geometry");
  }
  const texture::BarkTextures& textures =
      bark_textures ? *bark_textures : texture::bundled_bark_textures();
  const int bark = any_bark ? b.add_material("bark", false, textures) : -1;
  const int leaf = any_leaves ? b.add_material("leaf", true, textures) : -1;
  const int surface = any_surfaces ? b.add_surface_material() : -1;
  auto& model = b.model();
  const std::string tree = lods.front().name.substr(0, lods.front().name.rfind("_LOD"));
  const WindRig& rig = lods.front().wind_rig;
  for (const TreeMesh& m : lods) {
    tinygltf::Mesh mesh;
    mesh.name = m.name;
    if (!m.bark.empty()) mesh.primitives.push_back(b.add_part(m.bark, bark, rig, true));
    if (!m.leaves.empty()) mesh.primitives.push_back(b.add_part(m.leaves, leaf, rig, false));
    if (!m.surfaces.empty()) mesh.primitives.push_back(b.add_part(m.surfaces, surface, rig, false));
    if (mesh.primitives.empty()) throw MeshError("level of detail " + m.name + " has no geometry");
    model.meshes.push_back(std::move(mesh));
  }
  // Node 0, the scene's only node, shows LOD0. The coarser levels are nodes 1..n-1 that only
  // MSFT_lod names: a viewer without the extension draws LOD0 alone instead of every level on
  // top of each other, and one with it switches by the screen coverage hints. Each level's node
  // carries the same translation, since MSFT_lod puts a level in its root's place.
  tinygltf::Node root;
  root.name = tree;
  root.mesh = 0;
  // A skinned mesh's node transform does not apply (glTF 3.7.3.3): with the wind skin the local
  // origin moves to the root joints.
  if (rig.empty()) place_node(root, lods.front().origin);
  model.nodes.push_back(root);
  tinygltf::Value::Object extras;
  // The leaf clouds for 2.5D impostors (Burkus 6), for an engine to draw as `ramus view` does.
  if (!lods.front().leaves.empty()) extras["ramus_foliage"] = foliage_extras(lods.front());
  if (lods.size() > 1) {
    tinygltf::Value::Array ids, coverage;
    for (std::size_t k = 0; k < lods.size(); ++k) {
      coverage.emplace_back(screen_coverage(int(k), int(lods.size())));
      if (k == 0) continue;
      tinygltf::Node level;
      level.name = lods[k].name;
      level.mesh = int(k);
      if (rig.empty()) place_node(level, lods[k].origin);
      model.nodes.push_back(level);
      ids.emplace_back(int(k));
    }
    tinygltf::Value::Object ext;
    ext["ids"] = tinygltf::Value(std::move(ids));
    extras["MSFT_screencoverage"] = tinygltf::Value(std::move(coverage));
    model.nodes[0].extensions["MSFT_lod"] = tinygltf::Value(std::move(ext));
    model.extensionsUsed.push_back("MSFT_lod");
  }
  if (!extras.empty()) model.nodes[0].extras = tinygltf::Value(std::move(extras));
  const std::vector<int> joint_roots =
      rig.empty() ? std::vector<int>{} : add_wind(b, rig, lods.front().origin, int(lods.size()));
  tinygltf::Scene scene;
  scene.name = tree;
  scene.nodes = {0};
  scene.nodes.insert(scene.nodes.end(), joint_roots.begin(), joint_roots.end());
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  if (model.buffers[0].data.size() > 0xfffffff0ull) {
    throw MeshError(
        "the mesh needs a buffer larger than glTF's 4 GiB limit; use --lod or fewer modules");
  }
}

}  // namespace

GltfBytes encode_gltf(const std::vector<TreeMesh>& lods, bool binary, const std::string& bin_uri,
                      GltfCompression compression, const texture::BarkTextures* bark) {
  if (lods.empty()) throw MeshError("nothing to write: no meshes");
  ModelBuilder b;
  build_model(lods, bark, b);
  GltfBytes out;
  if (!binary) out.bin.assign(b.model().buffers[0].data.begin(), b.model().buffers[0].data.end());
  std::ostringstream glb;
  tinygltf::TinyGLTF gltf;
  if (!gltf.WriteGltfSceneToStream(&b.model(), glb, false, true)) {
    throw MeshError("glTF serialization failed");
  }
  if (compression != GltfCompression::kNone) {
    try {
      out.main = compress_glb(glb.str(), compression);
    } catch (const std::runtime_error& e) {
      throw MeshError(e.what());
    }
    if (binary) return out;
    out.bin = glb_bin(out.main);
    std::optional<std::string> json = gltf_json_with_buffer_uri(out.main, bin_uri);
    if (!json) throw MeshError("glTF serialization produced no buffer");
    out.main = std::move(*json);
    return out;
  }
  if (binary) {
    out.main = glb.str();
    return out;
  }
  // A .gltf is the GLB's JSON with the buffer pointing at the .bin file.
  std::optional<std::string> json = gltf_json_with_buffer_uri(glb.str(), bin_uri);
  if (!json) throw MeshError("glTF serialization produced no buffer");
  out.main = std::move(*json);
  return out;
}

void write_gltf(const std::vector<TreeMesh>& lods, const std::string& path,
                GltfCompression compression, const texture::BarkTextures* bark) {
  const bool written = write_gltf_files(path, [&](bool binary, const std::string& bin_uri) {
    return encode_gltf(lods, binary, bin_uri, compression, bark);
  });
  if (!written) throw MeshError("a glTF file name must end in .glb or .gltf: " + path);
}

}  // namespace ramus::mesh
