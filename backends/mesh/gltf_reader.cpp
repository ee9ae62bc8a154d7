// glTF 2.0 input for the preview, through tinygltf: the one reader in mesh/ that includes it
// (gltf_writer.cpp is the one writer). What is drawn is what a viewer shows of the default
// scene: every node's triangles under the product of its ancestors' transforms (matrix or TRS,
// spec 5.25), with MSFT_lod's coarser levels left out, since the node holding the extension is
// LOD0 and the levels it names are stand-ins for it, not more geometry. Skinned meshes are posed
// by linear blend skinning (the canonical pieces file), and EXT_mesh_gpu_instancing draws its
// mesh once per instance transform (the --gpu-instancing pieces file, as a viewer without a
// custom shader shows it). Then y up becomes z up.
#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>
#include <set>

#include "backends/mesh/gltf_accessors.h"
#include "backends/mesh/mesh_reader.h"
#include "core/up_axis.h"

namespace ramus::mesh {
namespace {

// A 4x4 affine transform, column-major like glTF (m[col * 4 + row]), in double so that the
// translation of a georeferenced node keeps its digits.
struct Affine {
  std::array<double, 16> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

  Affine operator*(const Affine& o) const {
    Affine r;
    for (int c = 0; c < 4; ++c) {
      for (int row = 0; row < 4; ++row) {
        double s = 0;
        for (int k = 0; k < 4; ++k) s += m[k * 4 + row] * o.m[c * 4 + k];
        r.m[c * 4 + row] = s;
      }
    }
    return r;
  }
  Vec3 column(int c) const { return {m[c * 4], m[c * 4 + 1], m[c * 4 + 2]}; }
  Vec3 point(const Vec3& p) const {
    return column(0) * p.x + column(1) * p.y + column(2) * p.z + column(3);
  }
  // Normals go by the inverse transpose of the linear part: its columns are the cross products
  // of the linear part's columns over the determinant (only the sign of which matters here).
  Vec3 normal(const Vec3& n) const {
    const Vec3 a = column(0), b = column(1), c = column(2);
    const double det = dot(a, cross(b, c));
    const Vec3 r = cross(b, c) * n.x + cross(c, a) * n.y + cross(a, b) * n.z;
    return det < 0 ? -r : r;
  }
};

Affine node_transform(const tinygltf::Node& n) {
  Affine a;
  if (n.matrix.size() == 16) {
    std::copy(n.matrix.begin(), n.matrix.end(), a.m.begin());
    return a;
  }
  // T * R * S (spec 5.25).
  if (n.scale.size() == 3) {
    for (int k = 0; k < 3; ++k) {
      for (int row = 0; row < 3; ++row) a.m[k * 4 + row] *= n.scale[k];
    }
  }
  if (n.rotation.size() == 4) {
    const double x = n.rotation[0], y = n.rotation[1], z = n.rotation[2], w = n.rotation[3];
    Affine r;
    r.m = {1 - 2 * (y * y + z * z),
           2 * (x * y + z * w),
           2 * (x * z - y * w),
           0,
           2 * (x * y - z * w),
           1 - 2 * (x * x + z * z),
           2 * (y * z + x * w),
           0,
           2 * (x * z + y * w),
           2 * (y * z - x * w),
           1 - 2 * (x * x + y * y),
           0,
           0,
           0,
           0,
           1};
    a = r * a;
  }
  if (n.translation.size() == 3) {
    for (int k = 0; k < 3; ++k) a.m[12 + k] = n.translation[k];
  }
  return a;
}

struct Reader {
  const tinygltf::Model& model;
  const std::string& path;
  std::set<int> lod_levels;    // nodes MSFT_lod names as coarser levels
  std::vector<Affine> worlds;  // every node's world transform (compute_worlds)
  ReadMeshBuilder out;

  [[noreturn]] void fail(const std::string& what) const { throw MeshError(path + ": " + what); }

  // The shared accessor reading (gltf_accessors.h), its errors named with the file.
  template <class Read>
  auto checked(const Read& read) const {
    try {
      return read();
    } catch (const gltf_accessors::AccessorError& e) {
      fail(e.what());
    }
  }
  const unsigned char* data(const tinygltf::Accessor& a, std::size_t& stride) const {
    return checked([&] { return gltf_accessors::element_data(model, a, stride); });
  }
  std::vector<Vec3> vec3s(int index, const char* what) const {
    return checked([&] { return gltf_accessors::vec3s(model, index, what); });
  }
  std::vector<std::uint32_t> indices(const tinygltf::Primitive& prim, std::size_t vertices) const {
    return checked([&] { return gltf_accessors::indices(model, prim, vertices); });
  }

  // Any accessor of `comps` components as doubles, row after row: float as it is, integers as
  // they are or, for normalized accessors, scaled to [0, 1] (weights, spec 3.11).
  std::vector<double> values(int index, int comps, const char* what) const {
    if (index < 0 || index >= int(model.accessors.size())) fail(std::string("no such ") + what);
    const tinygltf::Accessor& a = model.accessors[index];
    if (tinygltf::GetNumComponentsInType(a.type) != comps) {
      fail(std::string(what) + " has the wrong number of components");
    }
    std::size_t stride = 0;
    const unsigned char* p = data(a, stride);
    const int size = tinygltf::GetComponentSizeInBytes(a.componentType);
    std::vector<double> v(a.count * std::size_t(comps));
    for (std::size_t i = 0; i < a.count; ++i) {
      for (int c = 0; c < comps; ++c) {
        const unsigned char* q = p + i * stride + std::size_t(c) * std::size_t(size);
        double x = 0;
        if (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
          float f;
          std::memcpy(&f, q, 4);
          x = f;
        } else if (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
          x = a.normalized ? *q / 255.0 : *q;
        } else if (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
          std::uint16_t u;
          std::memcpy(&u, q, 2);
          x = a.normalized ? u / 65535.0 : u;
        } else {
          fail(std::string(what) + " has a component type the preview does not read");
        }
        v[i * std::size_t(comps) + std::size_t(c)] = x;
      }
    }
    return v;
  }

  // The world transform of every node (its ancestors' transforms times its own), whether or not
  // the scene draws it: skins name joints anywhere in the node tree.
  void compute_worlds() {
    std::vector<int> parent(model.nodes.size(), -1);
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
      for (int c : model.nodes[i].children) {
        if (c < 0 || c >= int(parent.size())) fail("a node reference is out of range");
        if (parent[c] >= 0) fail("a node has two parents");
        parent[c] = int(i);
      }
    }
    worlds.assign(model.nodes.size(), Affine{});
    std::vector<char> done(model.nodes.size(), 0);
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
      std::vector<int> chain;  // i and its ancestors not yet computed, nearest first
      for (int k = int(i); k >= 0 && !done[k]; k = parent[k]) {
        if (chain.size() > model.nodes.size()) fail("the node tree has a cycle");
        chain.push_back(k);
      }
      for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
        const int k = *it;
        worlds[k] =
            (parent[k] >= 0 ? worlds[parent[k]] : Affine{}) * node_transform(model.nodes[k]);
        done[k] = 1;
      }
    }
  }

  // The joint matrices of a skin (spec 3.7.3): a joint's world transform times its inverse bind
  // matrix. The skinned node's own transform is ignored, as the spec says.
  std::vector<Affine> joint_matrices(int skin) const {
    if (skin < 0 || skin >= int(model.skins.size())) fail("a node names a missing skin");
    const tinygltf::Skin& sk = model.skins[skin];
    std::vector<double> ibm;
    if (sk.inverseBindMatrices >= 0) {
      ibm = values(sk.inverseBindMatrices, 16, "inverseBindMatrices");
      if (ibm.size() != sk.joints.size() * 16) fail("a skin's inverse bind matrices miscount");
    }
    std::vector<Affine> m;
    for (std::size_t j = 0; j < sk.joints.size(); ++j) {
      const int joint = sk.joints[j];
      if (joint < 0 || joint >= int(worlds.size())) fail("a skin names a missing joint");
      Affine inv;
      if (!ibm.empty())
        std::copy(ibm.begin() + std::ptrdiff_t(j * 16), ibm.begin() + std::ptrdiff_t(j * 16 + 16),
                  inv.m.begin());
      m.push_back(worlds[joint] * inv);
    }
    return m;
  }

  // Each instance's transform of EXT_mesh_gpu_instancing (TRANSLATION, ROTATION, SCALE; what a
  // viewer without a custom shader draws), or one identity when the node has none.
  std::vector<Affine> instances(const tinygltf::Node& n) const {
    const auto ext = n.extensions.find("EXT_mesh_gpu_instancing");
    if (ext == n.extensions.end() || !ext->second.Has("attributes")) return {Affine{}};
    const tinygltf::Value& attrs = ext->second.Get("attributes");
    auto read = [&](const char* name, int comps) {
      return attrs.Has(name) ? values(attrs.Get(name).GetNumberAsInt(), comps, name)
                             : std::vector<double>{};
    };
    const std::vector<double> t = read("TRANSLATION", 3), r = read("ROTATION", 4),
                              s = read("SCALE", 3);
    const std::size_t count = std::max({t.size() / 3, r.size() / 4, s.size() / 3});
    std::vector<Affine> out;
    for (std::size_t i = 0; i < count; ++i) {
      tinygltf::Node trs;
      if (t.size() >= 3 * (i + 1)) trs.translation.assign(t.begin() + 3 * i, t.begin() + 3 * i + 3);
      if (r.size() >= 4 * (i + 1)) trs.rotation.assign(r.begin() + 4 * i, r.begin() + 4 * i + 4);
      if (s.size() >= 3 * (i + 1)) trs.scale.assign(s.begin() + 3 * i, s.begin() + 3 * i + 3);
      out.push_back(node_transform(trs));
    }
    return out;
  }

  bool is_leaf(int material) const {
    if (material < 0 || material >= int(model.materials.size())) return false;
    const tinygltf::Material& m = model.materials[material];
    // "surface": the turtle's polygons (leaves and petals of ABOP 5.2), drawn as leaves.
    return m.name == "leaf" || m.name == "surface" ||
           (!m.alphaMode.empty() && m.alphaMode != "OPAQUE");
  }

  // The node's triangles: placed by `world`, or skinned by linear blend skinning when the node
  // has a skin (the pose the file stores, as a viewer shows it).
  void mesh(const tinygltf::Node& node, const Affine& world) {
    if (node.mesh < 0 || node.mesh >= int(model.meshes.size())) fail("a node names a missing mesh");
    const std::vector<Affine> joints =
        node.skin >= 0 ? joint_matrices(node.skin) : std::vector<Affine>{};
    for (const tinygltf::Primitive& prim : model.meshes[node.mesh].primitives) {
      if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1) continue;  // points, lines
      const auto pos = prim.attributes.find("POSITION");
      if (pos == prim.attributes.end()) continue;
      std::vector<Vec3> p = vec3s(pos->second, "POSITION");
      std::vector<Vec3> n;
      const auto nor = prim.attributes.find("NORMAL");
      if (nor != prim.attributes.end()) {
        n = vec3s(nor->second, "NORMAL");
        if (n.size() != p.size()) fail("NORMAL and POSITION differ in count");
      }
      if (node.skin >= 0) {
        skin(prim, joints, p, n);
      } else {
        for (Vec3& v : p) v = world.point(v);
        for (Vec3& v : n) v = world.normal(v);
      }
      for (Vec3& v : p) v = y_up_to_z_up(v);
      for (Vec3& v : n) v = y_up_to_z_up(v);
      const std::vector<std::uint32_t> idx = indices(prim, p.size());
      const bool leaf = is_leaf(prim.material);
      for (std::size_t t = 0; t + 2 < idx.size(); t += 3) {
        const std::array<Vec3, 3> c{p[idx[t]], p[idx[t + 1]], p[idx[t + 2]]};
        if (n.empty()) {
          out.add(leaf, c, nullptr);
        } else {
          const std::array<Vec3, 3> cn{n[idx[t]], n[idx[t + 1]], n[idx[t + 2]]};
          out.add(leaf, c, &cn);
        }
      }
    }
  }

  // v' = sum_k weight_k * joint[k] * v over JOINTS_0 / WEIGHTS_0 (spec 3.7.3.3).
  void skin(const tinygltf::Primitive& prim, const std::vector<Affine>& joints,
            std::vector<Vec3>& p, std::vector<Vec3>& n) const {
    const auto j = prim.attributes.find("JOINTS_0");
    const auto w = prim.attributes.find("WEIGHTS_0");
    if (j == prim.attributes.end() || w == prim.attributes.end()) {
      fail("a skinned primitive has no JOINTS_0 or WEIGHTS_0");
    }
    const std::vector<double> ids = values(j->second, 4, "JOINTS_0");
    const std::vector<double> weights = values(w->second, 4, "WEIGHTS_0");
    if (ids.size() != 4 * p.size() || weights.size() != 4 * p.size()) {
      fail("JOINTS_0 or WEIGHTS_0 and POSITION differ in count");
    }
    for (std::size_t v = 0; v < p.size(); ++v) {
      Vec3 sp, sn;
      for (int k = 0; k < 4; ++k) {
        const double wk = weights[4 * v + std::size_t(k)];
        if (wk == 0) continue;
        const double id = ids[4 * v + std::size_t(k)];
        if (id < 0 || id >= double(joints.size())) fail("a vertex names a missing joint");
        const Affine& m = joints[std::size_t(id)];
        sp = sp + m.point(p[v]) * wk;
        if (!n.empty()) sn = sn + m.normal(n[v]) * wk;
      }
      p[v] = sp;
      if (!n.empty()) n[v] = sn;
    }
  }

  void node(int index, const Affine& parent, int depth) {
    if (index < 0 || index >= int(model.nodes.size()) || depth > 256) {
      fail("a node reference is out of range or cyclic");
    }
    if (lod_levels.count(index)) return;
    const tinygltf::Node& n = model.nodes[index];
    const Affine world = parent * node_transform(n);
    if (n.mesh >= 0) {
      for (const Affine& instance : instances(n)) mesh(n, world * instance);
    }
    for (int c : n.children) node(c, world, depth + 1);
  }

  void run() {
    // Compressed geometry has no plain accessors to read; say so rather than "no buffer view".
    for (const std::string& ext : model.extensionsRequired) {
      if (ext == "KHR_draco_mesh_compression" || ext == "EXT_meshopt_compression" ||
          ext == "KHR_mesh_quantization") {
        fail("it needs " + ext + ", which the preview does not decode");
      }
    }
    for (const tinygltf::Node& n : model.nodes) {
      const auto ext = n.extensions.find("MSFT_lod");
      if (ext == n.extensions.end() || !ext->second.Has("ids")) continue;
      const tinygltf::Value& ids = ext->second.Get("ids");
      for (std::size_t k = 0; k < ids.ArrayLen(); ++k)
        lod_levels.insert(ids.Get(int(k)).GetNumberAsInt());
    }
    compute_worlds();
    std::vector<int> roots;
    if (!model.scenes.empty()) {
      const int s = model.defaultScene >= 0 && model.defaultScene < int(model.scenes.size())
                        ? model.defaultScene
                        : 0;
      roots = model.scenes[s].nodes;
    } else {
      // No scene: every node that is nobody's child is a root.
      std::vector<bool> child(model.nodes.size(), false);
      for (const tinygltf::Node& n : model.nodes) {
        for (int c : n.children) {
          if (c >= 0 && c < int(child.size())) child[c] = true;
        }
      }
      for (std::size_t i = 0; i < child.size(); ++i) {
        if (!child[i]) roots.push_back(int(i));
      }
    }
    for (int r : roots) node(r, Affine{}, 0);
  }
};

// The picture needs geometry only: images stay undecoded (their bytes are still checked to be
// inside the buffer by tinygltf).
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                const unsigned char*, int, void*) {
  return true;
}

}  // namespace

TreeMesh read_gltf_mesh(const std::string& path) {
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&skip_image, nullptr);
  if (std::string e = gltf_accessors::load_model_file(loader, model, path); !e.empty()) {
    throw MeshError(path + ": " + e);
  }
  Reader r{model, path, {}, {}, ReadMeshBuilder(path)};
  r.run();
  return r.out.finish();
}

}  // namespace ramus::mesh
