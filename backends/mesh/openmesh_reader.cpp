// OBJ and PLY input for the preview, through OpenMesh (which writes them in
// openmesh_writer.cpp). Neither format fixes an up axis, so the file's own `up y|z` comment
// decides ("# up y" in OBJ, "comment up y" in a PLY header, as the writer puts them); without
// one, the writer's defaults: y for OBJ (Blender), z for PLY (CloudCompare). Bark and leaves are
// told apart by colour (the MTL's Kd read as face colours, or PLY vertex colours): greener than
// red is leaf.
#include "backends/mesh/mesh_reader.h"
#include "core/input_file.h"

// GCC 12 reports a false maybe-uninitialized inside OpenMesh's property containers.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <cctype>
#include <filesystem>
#include <fstream>

#include "core/up_axis.h"

namespace ramus::mesh {
namespace {

using OMesh = OpenMesh::TriMesh_ArrayKernelT<>;

// The up axis a comment at the top of the file states. OBJ comments may sit anywhere, but the
// writer puts them first, so the first 64 lines are enough; a PLY header ends at end_header.
UpAxis stated_up(const std::string& path, bool ply) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  const std::string key = ply ? "comment up " : "# up ";
  for (int n = 0; n < 64 && std::getline(in, line); ++n) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (ply && line == "end_header") break;
    if (line.rfind(key, 0) == 0 && line.size() == key.size() + 1) {
      const char axis = char(std::tolower(static_cast<unsigned char>(line.back())));
      if (axis == 'y') return UpAxis::kY;
      if (axis == 'z') return UpAxis::kZ;
    }
  }
  return ply ? UpAxis::kZ : UpAxis::kY;
}

bool greenish(const OMesh::Color& c) { return int(c[1]) > int(c[0]); }

}  // namespace

TreeMesh read_openmesh_mesh(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  const bool ply = ext == ".ply";
  if (!ply && ext != ".obj") throw MeshError(path + ": not an OBJ or PLY file");
  {
    std::ifstream probe(path, std::ios::binary);
    if (!probe) throw MeshError(path + ": cannot open the file");
  }
  // Library code does not print; OpenMesh reports every oddity on its log streams otherwise.
  omlog().disable();
  omout().disable();
  omerr().disable();
  OMesh om;
  om.request_vertex_normals();
  om.request_vertex_colors();
  om.request_face_colors();
  OpenMesh::IO::Options opt = OpenMesh::IO::Options::VertexNormal |
                              OpenMesh::IO::Options::VertexColor | OpenMesh::IO::Options::FaceColor;
  if (std::string e = input_file_size_error(path); !e.empty()) throw MeshError(path + ": " + e);
  if (!OpenMesh::IO::read_mesh(om, path, opt)) {
    throw MeshError(path + ": cannot read the " + std::string(ply ? "PLY" : "OBJ") + " file");
  }
  const bool up_y = stated_up(path, ply) == UpAxis::kY;
  auto world = [&](const OMesh::Point& p) {
    const Vec3 v{p[0], p[1], p[2]};
    return up_y ? y_up_to_z_up(v) : v;
  };
  const bool normals = opt.check(OpenMesh::IO::Options::VertexNormal);
  const bool vertex_colours = opt.check(OpenMesh::IO::Options::VertexColor);
  const bool face_colours = opt.check(OpenMesh::IO::Options::FaceColor);
  ReadMeshBuilder out(path);
  for (const auto f : om.faces()) {
    std::array<Vec3, 3> c, n;
    int k = 0, green = 0;
    for (const auto v : om.fv_range(f)) {
      if (k == 3) break;  // a TriMesh has triangles only
      c[k] = world(om.point(v));
      if (normals) n[k] = world(om.normal(v));
      if (vertex_colours) green += greenish(om.color(v));
      ++k;
    }
    if (k != 3) continue;
    const bool leaf = face_colours ? greenish(om.color(f)) : green >= 2;
    out.add(leaf, c, normals ? &n : nullptr);
  }
  return out.finish();
}

}  // namespace ramus::mesh
