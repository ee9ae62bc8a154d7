// OBJ (+ MTL) and PLY output, read back with OpenMesh.
#include <catch2/catch.hpp>

#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <filesystem>
#include <fstream>

#include "backends/mesh/openmesh_writer.h"
#include "core/atomic_file.h"
#include "tests/backends/synthetic_tree.h"

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

void read_back(const fs::path& path, const TreeMesh& m) {
  OMesh om;
  om.request_vertex_normals();
  om.request_vertex_texcoords2D();
  OpenMesh::IO::Options opt =
      OpenMesh::IO::Options::VertexNormal | OpenMesh::IO::Options::VertexTexCoord;
  REQUIRE(OpenMesh::IO::read_mesh(om, path.string(), opt));
  CHECK(om.n_faces() == m.triangle_count());
  CHECK(om.n_vertices() == m.bark.vertex_count() + m.leaves.vertex_count());
  CHECK(opt.check(OpenMesh::IO::Options::VertexNormal));
  // The first vertex survives the round trip.
  const auto p = om.point(OMesh::VertexHandle(0));
  CHECK(p[0] == Approx(m.bark.positions[0].x).margin(1e-5));
  CHECK(p[2] == Approx(m.bark.positions[0].z).margin(1e-5));
  const auto n = om.normal(OMesh::VertexHandle(0));
  CHECK(n[1] == Approx(m.bark.normals[0].y).margin(1e-5));
}

}  // namespace

TEST_CASE("OBJ with materials reads back with OpenMesh", "[meshio]") {
  const TreeMesh m = sample();
  const fs::path obj = scratch() / "tree.obj";
  write_openmesh(m, obj.string());
  read_back(obj, m);
  const std::string text = slurp(obj);
  CHECK(text.find("mtllib tree.mtl") != std::string::npos);
  CHECK(text.find("usemtl bark") < text.find("usemtl leaf"));
  CHECK(slurp(scratch() / "tree.mtl") == obj_material_library());
}

TEST_CASE("binary PLY reads back with OpenMesh", "[meshio]") {
  const TreeMesh m = sample();
  const fs::path ply = scratch() / "tree.ply";
  write_openmesh(m, ply.string());
  read_back(ply, m);
  CHECK(slurp(ply).find("format binary_little_endian") != std::string::npos);
}

TEST_CASE("OBJ and PLY are byte-identical for the same input", "[meshio]") {
  for (const char* name : {"a.obj", "a.ply"}) {
    write_openmesh(sample(), (scratch() / name).string());
    const std::string first = slurp(scratch() / name);
    write_openmesh(sample(), (scratch() / name).string());
    CHECK(slurp(scratch() / name) == first);
  }
}

TEST_CASE("OBJ and PLY writers fail cleanly", "[meshio]") {
  CHECK_THROWS_AS(write_openmesh(sample(), "/nonexistent-ramus-dir/t.ply"), WriteError);
  CHECK_FALSE(fs::exists("/nonexistent-ramus-dir/t.ply"));
  CHECK_THROWS_AS(write_openmesh(sample(), (scratch() / "t.stl").string()), MeshError);
  CHECK_THROWS_AS(write_openmesh(TreeMesh{}, (scratch() / "t.obj").string()), MeshError);
}
