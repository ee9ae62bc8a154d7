// A piece from a glTF 2.0 file (.gltf or .glb), read with tinygltf (this is the pieces back end's
// only file that reads it). glTF has no quads, so the piece's mesh is written as triangles in
// pairs: triangles 2i and 2i+1 share an edge and together make quad i. Rims are nodes named
// `rim:<name>` whose mesh has one primitive listing the six rim vertices in order (mode POINTS,
// LINE_LOOP or LINE_STRIP); they are matched to the piece's vertices by position. Node transforms
// are applied; vertices at the same position are merged (exporters split them at UV seams).
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>

#include "backends/mesh/gltf_accessors.h"
#include "backends/pieces/piece_build.h"

namespace ramus::pieces {

namespace {

// The shared accessor reading (backends/mesh/gltf_accessors.h), its errors named with the file.
std::vector<Vec3> read_vec3(const tinygltf::Model& m, int index, const std::string& path) {
  try {
    return gltf_accessors::vec3s(m, index, "POSITION");
  } catch (const gltf_accessors::AccessorError& e) {
    throw PiecesError(path + ": " + e.what());
  }
}

std::vector<std::uint32_t> read_indices(const tinygltf::Model& m, const tinygltf::Primitive& prim,
                                        std::size_t vertex_count, const std::string& path) {
  try {
    return gltf_accessors::indices(m, prim, vertex_count);
  } catch (const gltf_accessors::AccessorError& e) {
    throw PiecesError(path + ": " + e.what());
  }
}

Mat4 node_local(const tinygltf::Node& n) {
  Mat4 m;
  if (n.matrix.size() == 16) {
    for (int i = 0; i < 16; ++i) m.m[i] = n.matrix[i];
    return m;
  }
  Trs t;
  if (n.translation.size() == 3) t.t = {n.translation[0], n.translation[1], n.translation[2]};
  if (n.rotation.size() == 4) t.r = {n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]};
  Mat4 s;
  if (n.scale.size() == 3) {
    s(0, 0) = n.scale[0];
    s(1, 1) = n.scale[1];
    s(2, 2) = n.scale[2];
  }
  return t.matrix() * s;
}

struct Reader {
  Reader(const tinygltf::Model& model, const std::string& file) : m(model), path(file) {}
  const tinygltf::Model& m;
  const std::string& path;
  std::vector<Vec3> positions;  // merged
  std::map<std::array<long long, 3>, std::uint32_t> at;
  std::vector<std::array<std::uint32_t, 4>> quads;
  std::vector<std::pair<std::string, std::vector<Vec3>>> rim_points;
  double quantum = 1e-6;

  std::array<long long, 3> key(const Vec3& p) const {
    return {std::llround(p.x / quantum), std::llround(p.y / quantum), std::llround(p.z / quantum)};
  }
  std::uint32_t merge(const Vec3& p) {
    auto [it, fresh] = at.emplace(key(p), std::uint32_t(positions.size()));
    if (fresh) positions.push_back(p);
    return it->second;
  }

  void node(int index, const Mat4& parent, int depth) {
    if (index < 0 || index >= int(m.nodes.size()) || depth > 64) {
      throw PiecesError(path + ": a node reference is out of range or cyclic");
    }
    const tinygltf::Node& n = m.nodes[index];
    Mat4 world = parent * node_local(n);
    if (n.mesh >= 0 && n.mesh < int(m.meshes.size())) mesh(n, world);
    for (int c : n.children) node(c, world, depth + 1);
  }

  void mesh(const tinygltf::Node& n, const Mat4& world) {
    bool rim = n.name.rfind("rim:", 0) == 0;
    for (const tinygltf::Primitive& prim : m.meshes[n.mesh].primitives) {
      auto pos = prim.attributes.find("POSITION");
      if (pos == prim.attributes.end()) continue;
      std::vector<Vec3> p = read_vec3(m, pos->second, path);
      for (Vec3& v : p) v = world.point(v);
      std::vector<std::uint32_t> idx = read_indices(m, prim, p.size(), path);
      if (rim) {
        std::vector<Vec3> pts;
        for (std::uint32_t i : idx) pts.push_back(p[i]);
        rim_points.push_back({n.name.substr(4), pts});
        continue;
      }
      if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1) {
        throw PiecesError(path + ": mesh '" + m.meshes[n.mesh].name +
                          "' is not made of triangles (pairs of them form the quads)");
      }
      if (idx.size() % 6 != 0) {
        throw PiecesError(path + ": mesh '" + m.meshes[n.mesh].name +
                          "' has an odd number of triangles; pieces are quad meshes");
      }
      for (std::size_t t = 0; t < idx.size(); t += 6) {
        std::uint32_t a[3] = {merge(p[idx[t]]), merge(p[idx[t + 1]]), merge(p[idx[t + 2]])};
        std::uint32_t b[3] = {merge(p[idx[t + 3]]), merge(p[idx[t + 4]]), merge(p[idx[t + 5]])};
        quads.push_back(pair_quad(a, b, t / 6));
      }
    }
  }

  // The quad made of two triangles sharing an edge: the vertex of b not in a goes between the
  // shared edge's ends, keeping a's winding.
  std::array<std::uint32_t, 4> pair_quad(const std::uint32_t* a, const std::uint32_t* b,
                                         std::size_t q) const {
    for (int e = 0; e < 3; ++e) {
      std::uint32_t u = a[e], v = a[(e + 1) % 3];
      for (int f = 0; f < 3; ++f) {
        // b walks the shared edge the other way: v -> u.
        if (b[f] == v && b[(f + 1) % 3] == u) {
          std::uint32_t extra = b[(f + 2) % 3];
          return {a[(e + 2) % 3], u, extra, v};
        }
      }
    }
    throw PiecesError(path + ": triangles " + std::to_string(2 * q) + " and " +
                      std::to_string(2 * q + 1) + " share no edge, so they are not a quad");
  }
};

}  // namespace

PieceDraft draft_gltf_file(const std::string& name, const std::string& path,
                           const std::string* bytes) {
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string e;
  if (bytes) {
    // An embedded file is self-contained (the .rmb encoder refuses a .gltf whose buffers or
    // images are files): a damaged or crafted one that names a file reads nothing from disk.
    tinygltf::FsCallbacks no_files{};
    no_files.FileExists = [](const std::string&, void*) { return false; };
    no_files.ExpandFilePath = [](const std::string& p, void*) { return p; };
    no_files.ReadWholeFile = [](std::vector<unsigned char>*, std::string* e, const std::string& f,
                                void*) {
      if (e) *e += "an embedded glTF file cannot refer to the file " + f + "\n";
      return false;
    };
    no_files.WriteWholeFile = [](std::string*, const std::string&,
                                 const std::vector<unsigned char>&, void*) { return false; };
    loader.SetFsCallbacks(no_files);
    e = gltf_accessors::load_model(loader, model, path, *bytes, "");
  } else {
    e = gltf_accessors::load_model_file(loader, model, path);
  }
  if (!e.empty()) throw PiecesError(path + ": " + e);
  Reader r{model, path};
  // Merge tolerance: a millionth of the file's extent.
  double extent = 0;
  for (const tinygltf::Accessor& a : model.accessors) {
    for (std::size_t i = 0; i < a.maxValues.size() && i < a.minValues.size(); ++i) {
      extent = std::max(extent, std::abs(a.maxValues[i] - a.minValues[i]));
    }
  }
  r.quantum = std::max(extent, 1e-3) * 1e-6;
  int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
  if (scene < int(model.scenes.size())) {
    for (int n : model.scenes[scene].nodes) r.node(n, Mat4{}, 0);
  } else {
    for (std::size_t n = 0; n < model.nodes.size(); ++n) r.node(int(n), Mat4{}, 0);
  }
  std::vector<RawRim> rims;
  for (auto& [rim_name, pts] : r.rim_points) {
    RawRim rim;
    rim.name = rim_name;
    for (const Vec3& p : pts) {
      auto it = r.at.find(r.key(p));
      if (it == r.at.end()) {
        throw PiecesError(path + ": a vertex of rim:" + rim_name + " is not a vertex of the piece");
      }
      rim.vertices.push_back(it->second);
    }
    rims.push_back(std::move(rim));
  }
  return draft_from_raw(name, path, std::move(r.positions), std::move(r.quads), std::move(rims));
}

}  // namespace ramus::pieces
