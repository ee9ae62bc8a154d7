#include "backends/mesh/mesh_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>

#include "mesh/local_origin.h"

namespace ramus::mesh {

TreeMesh read_mesh_file(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".glb" || ext == ".gltf") return read_gltf_mesh(path);
  if (ext == ".obj" || ext == ".ply") return read_openmesh_mesh(path);
  throw MeshError(path + ": not a mesh file this reader knows (.glb, .gltf, .obj, .ply)");
}

void ReadMeshBuilder::add(bool leaf, const std::array<Vec3, 3>& p,
                          const std::array<Vec3, 3>* normals) {
  for (const Vec3& v : p) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
      throw MeshError(path_ + ": a vertex has a non-finite position");
    }
  }
  const Vec3 face = cross(p[1] - p[0], p[2] - p[0]);
  const double area = length(face);
  if (!(area > 0)) return;  // degenerate: nothing to draw, and no normal to light it by
  std::vector<Corner>& out = leaf ? leaves_ : bark_;
  for (int k = 0; k < 3; ++k) {
    Vec3 n = normals ? (*normals)[k] : Vec3{};
    const double len = length(n);
    n = std::isfinite(len) && len > 0 ? n / len : face / area;
    out.push_back({p[k], n});
  }
}

TreeMesh ReadMeshBuilder::finish() const {
  if (bark_.empty() && leaves_.empty()) throw MeshError(path_ + ": the mesh has no triangles");
  Vec3 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
          std::numeric_limits<double>::max()};
  Vec3 hi = -lo;
  for (const auto* part : {&bark_, &leaves_}) {
    for (const Corner& c : *part) {
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], c.position[k]);
        hi[k] = std::max(hi[k], c.position[k]);
      }
    }
  }
  // As local_origin does for skeletons: far from (0, 0, 0) the vertices are kept relative to a
  // whole-unit point at the base of the bounds, so floats keep millimetres.
  TreeMesh m;
  m.name = std::filesystem::path(path_).stem().string();
  const double reach = std::max({std::abs(lo.x), std::abs(lo.y), std::abs(lo.z), std::abs(hi.x),
                                 std::abs(hi.y), std::abs(hi.z)});
  if (reach > kFloatMillimetreRange) {
    m.origin = Vec3{std::round((lo.x + hi.x) / 2), std::round((lo.y + hi.y) / 2), std::round(lo.z)};
  }
  auto fill = [&](const std::vector<Corner>& in, MeshPart& part) {
    part.positions.reserve(in.size());
    part.normals.reserve(in.size());
    part.indices.reserve(in.size());
    for (const Corner& c : in) {
      part.indices.push_back(std::uint32_t(part.positions.size()));
      part.positions.push_back(Vec3f(c.position - m.origin));
      part.normals.push_back(Vec3f(c.normal));
    }
  };
  if (bark_.size() + leaves_.size() > std::numeric_limits<std::uint32_t>::max()) {
    throw MeshError(path_ + ": the mesh has too many triangles to draw");
  }
  fill(bark_, m.bark);
  fill(leaves_, m.leaves);
  return m;
}

}  // namespace ramus::mesh
