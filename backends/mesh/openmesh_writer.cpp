#include "backends/mesh/openmesh_writer.h"

// GCC 12 reports a false maybe-uninitialized inside OpenMesh's property containers.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <filesystem>
#include <sstream>

#include "backends/mesh/leaf_shape.h"
#include "backends/texture/bark_maps.h"
#include "core/atomic_file.h"
#include "core/number_text.h"

namespace ramus::mesh {
namespace {

using OMesh = OpenMesh::TriMesh_ArrayKernelT<>;

constexpr OpenMesh::Vec3uc kBarkColour{92, 66, 44};
constexpr OpenMesh::Vec3uc kLeafColour{70, 135, 45};

Vec3f axes(const Vec3f& v, UpAxis up) { return up == UpAxis::kY ? z_up_to_y_up(v) : v; }

void add_part(OMesh& om, const MeshPart& part, const OpenMesh::Vec3uc& colour, UpAxis up) {
  std::vector<OMesh::VertexHandle> vh(part.vertex_count());
  for (std::size_t i = 0; i < part.vertex_count(); ++i) {
    const Vec3f p = axes(part.positions[i], up);
    const Vec3f n = axes(part.normals[i], up);
    vh[i] = om.add_vertex(OMesh::Point(p.x, p.y, p.z));
    om.set_normal(vh[i], OMesh::Normal(n.x, n.y, n.z));
    om.set_texcoord2D(vh[i], OMesh::TexCoord2D(part.uvs[i][0], part.uvs[i][1]));
    om.set_color(vh[i], OMesh::Color(colour));
  }
  for (std::size_t t = 0; t < part.triangle_count(); ++t) {
    const auto* idx = &part.indices[3 * t];
    if (!om.add_face(vh[idx[0]], vh[idx[1]], vh[idx[2]]).is_valid()) {
      throw MeshError("OpenMesh rejected triangle " + std::to_string(t) + " (non-manifold)");
    }
  }
}

OMesh to_openmesh(const TreeMesh& mesh, UpAxis up) {
  OMesh om;
  om.request_vertex_normals();
  om.request_vertex_texcoords2D();
  om.request_vertex_colors();
  add_part(om, mesh.bark, kBarkColour, up);
  add_part(om, mesh.leaves, kLeafColour, up);
  add_part(om, mesh.surfaces, kLeafColour, up);
  return om;
}

std::string write_to_string(const OMesh& om, const std::string& ext, OpenMesh::IO::Options opt) {
  omlog().disable();  // library code does not print; OpenMesh logs every write otherwise
  std::ostringstream os;
  if (!OpenMesh::IO::write_mesh(om, os, ext, opt, 9)) {
    throw MeshError("OpenMesh could not encode the mesh as " + ext);
  }
  return os.str();
}

// "up y\norigin X Y Z\n" (each line after `prefix`): what a reader needs to put the vertices
// back into world coordinates. The origin is turned into the file's axes like the vertices, and
// written in shortest round-trip form, so it keeps every digit of the double.
std::string placement_comments(const std::string& prefix, const TreeMesh& mesh, UpAxis up) {
  const Vec3 o = up == UpAxis::kY ? z_up_to_y_up(mesh.origin) : mesh.origin;
  std::string s = prefix + (up == UpAxis::kY ? "up y\n" : "up z\n") + prefix + "origin ";
  append_shortest(s, o.x + 0.0);  // + 0.0: never "-0"
  s += ' ';
  append_shortest(s, o.y + 0.0);
  s += ' ';
  append_shortest(s, o.z + 0.0);
  return s + "\n";
}

// The PLY header with the placement comments after its format line (a header may hold comment
// lines anywhere before end_header; the binary body is untouched).
std::string add_ply_comments(const std::string& ply, const std::string& comments) {
  const std::size_t format = ply.find("\nformat ");
  const std::size_t at =
      format == std::string::npos ? std::string::npos : ply.find('\n', format + 1);
  if (at == std::string::npos) throw MeshError("OpenMesh wrote a PLY header without a format line");
  return ply.substr(0, at + 1) + comments + ply.substr(at + 1);
}

// Adds the placement comments, `mtllib` and the material switches: the bark faces come first,
// then the leaf faces, then the polygon organs' faces.
std::string add_materials(const std::string& obj, const std::string& header,
                          const std::string& mtl_name, std::size_t bark_faces,
                          std::size_t leaf_faces, std::size_t surface_faces) {
  std::istringstream in(obj);
  std::string out = "# ramus tree mesh\n" + header + "mtllib " + mtl_name + "\n";
  out.reserve(obj.size() + 64);
  std::string line;
  std::size_t faces = 0;
  while (std::getline(in, line)) {
    if (line.rfind("f ", 0) == 0) {
      if (faces == 0 && bark_faces > 0) out += "usemtl bark\n";
      if (faces == bark_faces && leaf_faces > 0) out += "usemtl leaf\n";
      if (faces == bark_faces + leaf_faces && surface_faces > 0) out += "usemtl surface\n";
      ++faces;
    }
    out += line;
    out += '\n';
  }
  return out;
}

}  // namespace

// Kd multiplies the maps in most viewers, so it stays near white; its tint (redder bark, greener
// leaves) is what tells bark from leaf faces when the OBJ is read back (openmesh_reader.cpp).
std::string obj_material_library(const std::string& stem) {
  return "# ramus tree materials (docs/textures.md)\n"
         "newmtl bark\nKa 0 0 0\nKd 1 0.96 0.92\nKs 0.02 0.02 0.02\nNs 8\nd 1\nillum 2\n"
         "map_Kd " +
         stem + "_bark.jpg\nbump " + stem + "_bark_height.jpg\nnorm " + stem +
         "_bark_normal.jpg\n\n"
         "newmtl leaf\nKa 0 0 0\nKd 0.92 1 0.9\nKs 0.05 0.05 0.05\nNs 16\nd 1\nillum 2\n"
         "map_Kd " +
         stem + "_leaf.png\nmap_d " + stem +
         "_leaf.png\n\n"
         // The polygon organs (ABOP `{ . }`) stay untextured: their UVs are planar, for a user's
         // own texture.
         "newmtl surface\nKa 0 0 0\nKd 0.275 0.529 0.176\nKs 0.05 0.05 0.05\nNs 16\nd 1\nillum 2\n";
}

void write_openmesh(const TreeMesh& mesh, const std::string& path, UpAxis up,
                    const texture::BarkTextures* bark_textures) {
  if (mesh.bark.empty() && mesh.leaves.empty() && mesh.surfaces.empty())
    throw MeshError("nothing to write: the tree has no geometry");
  const std::filesystem::path p(path);
  const std::string ext = p.extension().string();
  OpenMesh::IO::Options opt =
      OpenMesh::IO::Options::VertexNormal | OpenMesh::IO::Options::VertexTexCoord;
  if (ext == ".ply") {
    opt += OpenMesh::IO::Options::Binary;
    opt += OpenMesh::IO::Options::LSB;
    opt += OpenMesh::IO::Options::VertexColor;
    write_file_atomically(path,
                          add_ply_comments(write_to_string(to_openmesh(mesh, up), ".ply", opt),
                                           placement_comments("comment ", mesh, up)));
    return;
  }
  if (ext != ".obj") throw MeshError("unknown mesh file extension '" + ext + "': " + path);
  std::filesystem::path mtl = p;
  mtl.replace_extension(".mtl");
  const std::string obj = write_to_string(to_openmesh(mesh, up), ".obj", opt);
  const std::string stem = p.stem().string();
  const texture::BarkTextures& bark =
      bark_textures ? *bark_textures : texture::bundled_bark_textures();
  auto beside = [&](const std::string& name) { return (p.parent_path() / name).string(); };
  write_file_atomically(beside(stem + "_bark.jpg"), bark.base);
  write_file_atomically(beside(stem + "_bark_height.jpg"), bark.height);
  write_file_atomically(beside(stem + "_bark_normal.jpg"), bark.normal);
  write_file_atomically(beside(stem + "_leaf.png"), leaf_texture_png(512, 1024));
  write_file_atomically(mtl.string(), obj_material_library(stem));
  write_file_atomically(
      path, add_materials(obj, placement_comments("# ", mesh, up), mtl.filename().string(),
                          mesh.bark.triangle_count(), mesh.leaves.triangle_count(),
                          mesh.surfaces.triangle_count()));
}

}  // namespace ramus::mesh
