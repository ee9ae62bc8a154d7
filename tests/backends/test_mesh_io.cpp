// OBJ (+ MTL) and PLY output, read back with OpenMesh.
#include <catch2/catch.hpp>

#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <filesystem>
#include <fstream>

#include "backends/mesh/openmesh_writer.h"
#include "core/atomic_file.h"
#include "tests/mesh/synthetic_tree.h"

using namespace ramus;
using namespace ramus::mesh;
namespace fs = std::filesystem;
using OMesh = OpenMesh::TriMesh_ArrayKernelT<>;

namespace {

fs::path scratch() {
  const fs::path dir = fs::path(RAMUS_BINARY_DIR) / "test-output" / "meshio";
  fs::create_directories(dir);
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

TreeMesh sample() { return build_tree_mesh(testing::synthetic_tree(4, 400), {}); }

// The vertex as the file should hold it: the mesh's z-up vertex, turned for a y-up file.
Vec3f in_file(const Vec3f& v, UpAxis up) { return up == UpAxis::kY ? Vec3f{v.x, v.z, -v.y} : v; }

void read_back(const fs::path& path, const TreeMesh& m, UpAxis up) {
  OMesh om;
  om.request_vertex_normals();
  om.request_vertex_texcoords2D();
  OpenMesh::IO::Options opt =
      OpenMesh::IO::Options::VertexNormal | OpenMesh::IO::Options::VertexTexCoord;
  REQUIRE(OpenMesh::IO::read_mesh(om, path.string(), opt));
  CHECK(om.n_faces() == m.triangle_count());
  CHECK(om.n_vertices() == m.bark.vertex_count() + m.leaves.vertex_count());
  CHECK(opt.check(OpenMesh::IO::Options::VertexNormal));
  // Every vertex survives the round trip, in the file's axes.
  for (std::size_t i = 0; i < m.bark.vertex_count(); i += 97) {
    const auto p = om.point(OMesh::VertexHandle(int(i)));
    const Vec3f want = in_file(m.bark.positions[i], up);
    CHECK(p[0] == Approx(want.x).margin(1e-5));
    CHECK(p[1] == Approx(want.y).margin(1e-5));
    CHECK(p[2] == Approx(want.z).margin(1e-5));
    const auto n = om.normal(OMesh::VertexHandle(int(i)));
    const Vec3f wn = in_file(m.bark.normals[i], up);
    CHECK(n[1] == Approx(wn.y).margin(1e-5));
    CHECK(n[2] == Approx(wn.z).margin(1e-5));
  }
}

}  // namespace

TEST_CASE("OBJ with materials reads back with OpenMesh, y up and z up", "[meshio]") {
  const TreeMesh m = sample();
  for (UpAxis up : {UpAxis::kY, UpAxis::kZ}) {
    const fs::path obj = scratch() / "tree.obj";
    write_openmesh(m, obj.string(), up);
    read_back(obj, m, up);
    const std::string text = slurp(obj);
    CHECK(text.find(up == UpAxis::kY ? "\n# up y\n" : "\n# up z\n") != std::string::npos);
    CHECK(text.find("\n# origin 0 0 0\n") != std::string::npos);
    CHECK(text.find("mtllib tree.mtl") != std::string::npos);
    CHECK(text.find("usemtl bark") < text.find("usemtl leaf"));
    CHECK(slurp(scratch() / "tree.mtl") == obj_material_library("tree"));
    // The pictures the MTL names lie beside it.
    for (const char* f :
         {"tree_bark.jpg", "tree_bark_height.jpg", "tree_bark_normal.jpg", "tree_leaf.png"})
      CHECK(fs::file_size(scratch() / f) > 1000);
  }
}

TEST_CASE("binary PLY reads back with OpenMesh, y up and z up", "[meshio]") {
  const TreeMesh m = sample();
  for (UpAxis up : {UpAxis::kY, UpAxis::kZ}) {
    const fs::path ply = scratch() / "tree.ply";
    write_openmesh(m, ply.string(), up);
    read_back(ply, m, up);
    const std::string text = slurp(ply);
    const std::string header = text.substr(0, text.find("end_header"));
    CHECK(header.find("format binary_little_endian") != std::string::npos);
    CHECK(header.find(up == UpAxis::kY ? "\ncomment up y\n" : "\ncomment up z\n") !=
          std::string::npos);
    CHECK(header.find("\ncomment origin 0 0 0\n") != std::string::npos);
  }
}

TEST_CASE("OBJ and PLY record a georeferenced mesh's origin in the file's axes", "[meshio]") {
  TreeMesh m = sample();
  m.origin = {1180123.5, 2860456.25, 101};
  write_openmesh(m, (scratch() / "geo.obj").string(), UpAxis::kY);
  CHECK(slurp(scratch() / "geo.obj").find("\n# origin 1180123.5 101 -2860456.25\n") !=
        std::string::npos);
  write_openmesh(m, (scratch() / "geo.ply").string(), UpAxis::kZ);
  CHECK(slurp(scratch() / "geo.ply").find("\ncomment origin 1180123.5 2860456.25 101\n") !=
        std::string::npos);
}

TEST_CASE("OBJ and PLY are byte-identical for the same input", "[meshio]") {
  for (const char* name : {"a.obj", "a.ply"}) {
    write_openmesh(sample(), (scratch() / name).string(), UpAxis::kY);
    const std::string first = slurp(scratch() / name);
    write_openmesh(sample(), (scratch() / name).string(), UpAxis::kY);
    CHECK(slurp(scratch() / name) == first);
  }
}

TEST_CASE("OBJ and PLY writers fail cleanly", "[meshio]") {
  CHECK_THROWS_AS(write_openmesh(sample(), "/nonexistent-ramus-dir/t.ply", UpAxis::kZ), WriteError);
  CHECK_FALSE(fs::exists("/nonexistent-ramus-dir/t.ply"));
  CHECK_THROWS_AS(write_openmesh(sample(), (scratch() / "t.stl").string(), UpAxis::kZ), MeshError);
  CHECK_THROWS_AS(write_openmesh(TreeMesh{}, (scratch() / "t.obj").string(), UpAxis::kY),
                  MeshError);
}
