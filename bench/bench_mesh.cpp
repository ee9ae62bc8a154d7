// Meshing throughput: a skeleton of one million segments -> TreeMesh -> .glb.
//   bench_mesh [OUT.glb] [SEGMENTS]
// Prints triangles per second for meshing and for glTF encoding, and the .glb's bytes per
// triangle. bench/mesh_draco.sh compares that size with the same file compressed by Draco.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "backends/mesh/gltf_writer.h"
#include "mesh/tree_mesh.h"
#include "core/atomic_file.h"
#include "tests/mesh/synthetic_tree.h"

int main(int argc, char** argv) {
  using clock = std::chrono::steady_clock;
  const std::string out = argc > 1 ? argv[1] : "mesh_1m.glb";
  const std::size_t segments = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1'000'000;
  const ramus::Skeleton s = ramus::testing::synthetic_tree(1, segments);
  std::printf("skeleton: %zu nodes (%zu segments), %zu organs\n", s.size(),
              s.size() - s.roots().size(), s.organs.size());
  ramus::mesh::MeshOptions o;
  const auto t0 = clock::now();
  const ramus::mesh::TreeMesh m = ramus::mesh::build_tree_mesh(s, o);
  const auto t1 = clock::now();
  const auto bytes = ramus::mesh::encode_gltf({m}, true);
  const auto t2 = clock::now();
  ramus::write_file_atomically(out, bytes.main);
  const double mesh_s = std::chrono::duration<double>(t1 - t0).count();
  const double enc_s = std::chrono::duration<double>(t2 - t1).count();
  const double tris = double(m.triangle_count());
  std::printf("triangles: %.0f (bark %zu, leaves %zu), vertices %zu\n", tris,
              m.bark.triangle_count(), m.leaves.triangle_count(),
              m.bark.vertex_count() + m.leaves.vertex_count());
  std::printf("meshing: %.3f s, %.2f M triangles/s\n", mesh_s, tris / mesh_s / 1e6);
  std::printf("glb encoding: %.3f s, %.2f M triangles/s\n", enc_s, tris / enc_s / 1e6);
  std::printf("glb: %zu bytes, %.2f bytes/triangle -> %s\n", bytes.main.size(),
              double(bytes.main.size()) / tris, out.c_str());
  return 0;
}
