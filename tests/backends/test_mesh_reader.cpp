// Reading meshes back for the preview (backends/mesh/mesh_reader.h): every file ramus writes
// comes back in the z-up world it was written from, whatever the file's axes, with the
// georeferenced origin in place, LOD0 only behind MSFT_lod, and broken files refused.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <limits>

#include "backends/mesh/gltf_writer.h"
#include "backends/mesh/mesh_reader.h"
#include "backends/mesh/openmesh_writer.h"
#include "tests/mesh/synthetic_tree.h"

using namespace ramus;
using namespace ramus::mesh;

namespace {

namespace fs = std::filesystem;

fs::path scratch() {
  const fs::path dir = fs::path(RAMUS_BINARY_DIR) / "test-output" / "mesh-reader";
  fs::create_directories(dir);
  return dir;
}

struct Box {
  Vec3 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
          std::numeric_limits<double>::max()};
  Vec3 hi{-std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
          -std::numeric_limits<double>::max()};
};

// World bounds (origin + vertex) of both parts.
Box world_box(const TreeMesh& m) {
  Box b;
  for (const MeshPart* part : {&m.bark, &m.leaves}) {
    for (const Vec3f& p : part->positions) {
      const Vec3 w = m.origin + Vec3(p);
      for (int k = 0; k < 3; ++k) {
        b.lo[k] = std::min(b.lo[k], w[k]);
        b.hi[k] = std::max(b.hi[k], w[k]);
      }
    }
  }
  return b;
}

void check_same_box(const TreeMesh& read, const TreeMesh& written, double tol) {
  const Box a = world_box(read), b = world_box(written);
  for (int k = 0; k < 3; ++k) {
    CHECK(a.lo[k] == Approx(b.lo[k]).margin(tol));
    CHECK(a.hi[k] == Approx(b.hi[k]).margin(tol));
  }
}

TreeMesh tree(std::uint64_t seed = 5) {
  return build_tree_mesh(testing::synthetic_tree(seed, 300), {});
}

}  // namespace

TEST_CASE("glb, gltf, obj and ply come back z up with their triangles", "[mesh][reader]") {
  const TreeMesh m = tree();
  const fs::path dir = scratch();
  write_gltf({m}, (dir / "t.glb").string());
  write_gltf({m}, (dir / "t.gltf").string());
  write_openmesh(m, (dir / "ty.obj").string(), UpAxis::kY);
  write_openmesh(m, (dir / "tz.obj").string(), UpAxis::kZ);
  write_openmesh(m, (dir / "ty.ply").string(), UpAxis::kY);
  write_openmesh(m, (dir / "tz.ply").string(), UpAxis::kZ);
  for (const char* name : {"t.glb", "t.gltf", "ty.obj", "tz.obj", "ty.ply", "tz.ply"}) {
    INFO(name);
    const TreeMesh r = read_mesh_file((dir / name).string());
    CHECK(r.bark.triangle_count() == m.bark.triangle_count());
    CHECK(r.leaves.triangle_count() == m.leaves.triangle_count());
    check_same_box(r, m, 1e-4);
    // The tree is taller (z) than it is wide: it stands up.
    const Box b = world_box(r);
    CHECK(b.hi.z - b.lo.z > b.hi.x - b.lo.x);
  }
}

TEST_CASE("a georeferenced glb keeps its root translation and an MSFT_lod glb shows LOD0",
          "[mesh][reader]") {
  Skeleton s = testing::synthetic_tree(7, 300);
  const Vec3 utm{512345.25, 4123456.75, 87.5};
  for (SkeletonNode& n : s.nodes) n.position = n.position + utm;
  for (OrganAnchor& o : s.organs) o.position = o.position + utm;
  MeshOptions o;
  o.lod_count = 3;
  const std::vector<TreeMesh> lods = build_tree_lods(s, o);
  REQUIRE(lods[0].origin != Vec3{});
  const fs::path path = scratch() / "geo.glb";
  write_gltf(lods, path.string());
  const TreeMesh r = read_mesh_file(path.string());
  CHECK(r.bark.triangle_count() == lods[0].bark.triangle_count());
  CHECK(r.leaves.triangle_count() == lods[0].leaves.triangle_count());
  check_same_box(r, lods[0], 1e-3);  // millimetres at UTM scale
  CHECK(world_box(r).lo.x > 500000);
}

TEST_CASE("broken mesh files are MeshErrors naming the file", "[mesh][reader]") {
  const fs::path dir = scratch();
  write_gltf({tree()}, (dir / "whole.glb").string());
  std::string bytes;
  {
    std::ifstream in(dir / "whole.glb", std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::ofstream(dir / "cut.glb", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  std::ofstream(dir / "junk.obj") << "this is not\nan OBJ file\n";
  std::ofstream(dir / "loose.obj") << "v 0 0 0\nv 1 0 0\nf 1 2 9\n";
  // A buffer whose URI names a directory: tinygltf took its size for 2^63 - 1 bytes.
  fs::create_directories(dir / "folder");
  std::ofstream(dir / "dir_buffer.gltf")
      << R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":8,"uri":"folder"}]})";
  for (const char* name : {"cut.glb", "junk.obj", "loose.obj", "missing.ply", "dir_buffer.gltf"}) {
    INFO(name);
    try {
      read_mesh_file((dir / name).string());
      FAIL("no error");
    } catch (const MeshError& e) {
      CHECK(std::string(e.what()).find(name) != std::string::npos);
    }
  }
  CHECK_THROWS_AS(read_mesh_file((dir / "t.stl").string()), MeshError);
}
