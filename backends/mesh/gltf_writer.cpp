// The only file that includes tiny_gltf.h (its implementation lives in Debian's libtinygltf).
// Every buffer view starts on a 4-byte boundary, attribute views carry the ARRAY_BUFFER target and
// index views ELEMENT_ARRAY_BUFFER, and every accessor has exact min/max (taken from the float
// values written), which is what the Khronos glTF-Validator checks.
#include "backends/mesh/gltf_writer.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <limits>
#include <sstream>

#include "backends/mesh/leaf_shape.h"
#include "core/atomic_file.h"

namespace ramus::mesh {
namespace {

class ModelBuilder {
 public:
  ModelBuilder() {
    model_.asset.version = "2.0";
    model_.asset.generator = "ramus";
    model_.buffers.emplace_back();
  }

  int add_view(const void* data, std::size_t bytes, int target) {
    auto& buf = model_.buffers[0].data;
    while (buf.size() % 4) buf.push_back(0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buf.size();
    view.byteLength = bytes;
    view.target = target;
    const auto* p = static_cast<const unsigned char*>(data);
    buf.insert(buf.end(), p, p + bytes);
    model_.bufferViews.push_back(view);
    return int(model_.bufferViews.size() - 1);
  }

  // A float accessor over `count` elements of `comps` components each.
  template <typename T>
  int add_float_attribute(const std::vector<T>& values, int comps, int type) {
    const float* f = reinterpret_cast<const float*>(values.data());
    static_assert(sizeof(T) % sizeof(float) == 0);
    std::vector<double> lo(comps, std::numeric_limits<double>::infinity());
    std::vector<double> hi(comps, -std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < values.size(); ++i) {
      for (int c = 0; c < comps; ++c) {
        lo[c] = std::min(lo[c], double(f[i * comps + c]));
        hi[c] = std::max(hi[c], double(f[i * comps + c]));
      }
    }
    const int view =
        add_view(f, values.size() * comps * sizeof(float), TINYGLTF_TARGET_ARRAY_BUFFER);
    return add_accessor(view, TINYGLTF_COMPONENT_TYPE_FLOAT, values.size(), type, lo, hi);
  }

  int add_indices(const std::vector<std::uint32_t>& idx, std::size_t vertex_count) {
    const std::uint32_t hi = idx.empty() ? 0 : *std::max_element(idx.begin(), idx.end());
    const std::uint32_t lo = idx.empty() ? 0 : *std::min_element(idx.begin(), idx.end());
    int view;
    int type;
    // 16-bit indices when they fit; 65535 is the primitive-restart value and is never an index.
    if (vertex_count < 0xffff) {
      std::vector<std::uint16_t> small(idx.begin(), idx.end());
      view = add_view(small.data(), small.size() * 2, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
      type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    } else {
      view = add_view(idx.data(), idx.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
      type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    }
    return add_accessor(view, type, idx.size(), TINYGLTF_TYPE_SCALAR, {double(lo)}, {double(hi)});
  }

  int add_texture(const std::string& png, const std::string& name, int wrap) {
    tinygltf::Image image;
    image.name = name;
    image.mimeType = "image/png";
    image.bufferView = add_view(png.data(), png.size(), 0);
    model_.images.push_back(image);
    tinygltf::Sampler sampler;
    sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
    sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
    sampler.wrapS = sampler.wrapT = wrap;
    model_.samplers.push_back(sampler);
    tinygltf::Texture tex;
    tex.sampler = tex.source = int(model_.images.size() - 1);
    model_.textures.push_back(tex);
    return int(model_.textures.size() - 1);
  }

  int add_material(const std::string& name, bool leaf) {
    const int tex =
        leaf ? add_texture(leaf_texture_png(64, 128), "leaf", TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE)
             : add_texture(bark_texture_png(64, 64), "bark", TINYGLTF_TEXTURE_WRAP_REPEAT);
    tinygltf::Material m;
    m.name = name;
    m.pbrMetallicRoughness.baseColorTexture.index = tex;
    m.pbrMetallicRoughness.metallicFactor = 0.0;
    m.pbrMetallicRoughness.roughnessFactor = leaf ? 0.6 : 0.9;
    if (leaf) {
      // Every leaf card carries a back face of its own, so the material stays single-sided.
      m.alphaMode = "MASK";
      m.alphaCutoff = 0.5;
      m.doubleSided = false;
    }
    model_.materials.push_back(m);
    return int(model_.materials.size() - 1);
  }

  tinygltf::Primitive add_part(const MeshPart& part, int material) {
    tinygltf::Primitive prim;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    prim.material = material;
    prim.attributes["POSITION"] = add_float_attribute(part.positions, 3, TINYGLTF_TYPE_VEC3);
    prim.attributes["NORMAL"] = add_float_attribute(part.normals, 3, TINYGLTF_TYPE_VEC3);
    prim.attributes["TEXCOORD_0"] = add_float_attribute(part.uvs, 2, TINYGLTF_TYPE_VEC2);
    prim.attributes["_WIND"] = add_float_attribute(part.wind, 4, TINYGLTF_TYPE_VEC4);
    prim.indices = add_indices(part.indices, part.vertex_count());
    return prim;
  }

  tinygltf::Model& model() { return model_; }

 private:
  int add_accessor(int view, int component, std::size_t count, int type, std::vector<double> lo,
                   std::vector<double> hi) {
    tinygltf::Accessor a;
    a.bufferView = view;
    a.byteOffset = 0;
    a.componentType = component;
    a.count = count;
    a.type = type;
    a.minValues = std::move(lo);
    a.maxValues = std::move(hi);
    model_.accessors.push_back(a);
    return int(model_.accessors.size() - 1);
  }

  tinygltf::Model model_;
};

void build_model(const std::vector<TreeMesh>& lods, ModelBuilder& b) {
  bool any_bark = false, any_leaves = false;
  for (const TreeMesh& m : lods) {
    any_bark = any_bark || !m.bark.empty();
    any_leaves = any_leaves || !m.leaves.empty();
  }
  if (!any_bark && !any_leaves) throw MeshError("nothing to write: the tree has no geometry");
  const int bark = any_bark ? b.add_material("bark", false) : -1;
  const int leaf = any_leaves ? b.add_material("leaf", true) : -1;
  auto& model = b.model();
  const std::string tree = lods.front().name.substr(0, lods.front().name.rfind("_LOD"));
  model.nodes.emplace_back();
  model.nodes[0].name = tree;
  for (const TreeMesh& m : lods) {
    tinygltf::Mesh mesh;
    mesh.name = m.name;
    if (!m.bark.empty()) mesh.primitives.push_back(b.add_part(m.bark, bark));
    if (!m.leaves.empty()) mesh.primitives.push_back(b.add_part(m.leaves, leaf));
    if (mesh.primitives.empty()) throw MeshError("level of detail " + m.name + " has no geometry");
    model.meshes.push_back(std::move(mesh));
  }
  if (lods.size() == 1) {
    model.nodes[0].mesh = 0;
  } else {
    for (std::size_t k = 0; k < lods.size(); ++k) {
      tinygltf::Node child;
      child.name = lods[k].name;
      child.mesh = int(k);
      model.nodes.push_back(child);
      model.nodes[0].children.push_back(int(k + 1));
    }
  }
  tinygltf::Scene scene;
  scene.name = tree;
  scene.nodes = {0};
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  if (model.buffers[0].data.size() > 0xfffffff0ull) {
    throw MeshError(
        "the mesh needs a buffer larger than glTF's 4 GiB limit; use --lod or fewer modules");
  }
}

// The JSON chunk of a GLB container.
std::string glb_json(const std::string& glb) {
  std::uint32_t len = 0;
  std::memcpy(&len, glb.data() + 12, 4);
  std::string json = glb.substr(20, len);
  while (!json.empty() && json.back() == ' ') json.pop_back();
  return json;
}

std::string uri_escape(const std::string& s) {
  static const char* hex = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : s) {
    if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~') {
      out += char(c);
    } else {
      out += '%';
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  return out;
}

}  // namespace

GltfBytes encode_gltf(const std::vector<TreeMesh>& lods, bool binary, const std::string& bin_uri) {
  if (lods.empty()) throw MeshError("nothing to write: no meshes");
  ModelBuilder b;
  build_model(lods, b);
  GltfBytes out;
  if (!binary) out.bin.assign(b.model().buffers[0].data.begin(), b.model().buffers[0].data.end());
  std::ostringstream glb;
  tinygltf::TinyGLTF gltf;
  if (!gltf.WriteGltfSceneToStream(&b.model(), glb, false, true)) {
    throw MeshError("glTF serialization failed");
  }
  if (binary) {
    out.main = glb.str();
    return out;
  }
  // A .gltf is the GLB's JSON with the buffer pointing at the .bin file.
  std::string json = glb_json(glb.str());
  const std::string key = "\"buffers\":[{";
  const std::size_t at = json.find(key);
  if (at == std::string::npos) throw MeshError("glTF serialization produced no buffer");
  json.insert(at + key.size(), "\"uri\":\"" + uri_escape(bin_uri) + "\",");
  out.main = json + "\n";
  return out;
}

void write_gltf(const std::vector<TreeMesh>& lods, const std::string& path) {
  const std::filesystem::path p(path);
  const std::string ext = p.extension().string();
  if (ext == ".glb") {
    write_file_atomically(path, encode_gltf(lods, true).main);
    return;
  }
  if (ext != ".gltf") throw MeshError("a glTF file name must end in .glb or .gltf: " + path);
  std::filesystem::path bin = p;
  bin.replace_extension(".bin");
  const GltfBytes bytes = encode_gltf(lods, false, bin.filename().string());
  write_file_atomically(bin.string(), bytes.bin);
  write_file_atomically(path, bytes.main);
}

}  // namespace ramus::mesh
