// The pieces back end against the mesh back end on the same trees: assembles N trees (default
// 1,000) of 200-2,000 pieces each (Burkus et al. 2017, section 4.2) and encodes every tree in each
// pieces encoding (canonical glTF, --flatten, --gpu-instancing, the instance buffer), then meshes
// the same trees with the mesh back end (build_tree_mesh on a skeleton through the trees' joints)
// and encodes that as .glb. Prints pieces per second and bytes per instance (placed piece) for
// every encoding; all encoding happens in memory. The placed-pieces stream of an .rmb (section
// 12) is measured beside the instance buffer it expands to: the whole section, its tree records
// alone (what a piece costs once the set's header is there) and a pieces-only .rmb compressed
// with zstd; every tree's expansion is checked to equal its instance buffer byte for byte.
//   bench_pieces [TREES] [SEED]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "backends/mesh/gltf_writer.h"
#include "mesh/tree_mesh.h"
#include "backends/pieces/gltf_pieces.h"
#include "backends/pieces/output_instance_buffer.h"
#include "backends/pieces/output_layout.h"
#include "backends/pieces/output_piece_stream.h"
#include "backends/pieces/pieces.h"
#include "bench/bench_pieces_trees.h"
#include "core/rng.h"
#include "formats/rmb/rmb_codec.h"
#include "formats/rmb/rmb_piece_stream_expand.h"

using namespace ramus;
using namespace ramus::pieces;

namespace {

// The same tree as a skeleton for the mesh back end: one node at the tree's root joint and one
// at every terminal joint, radius the rim radius scaled like the joint.
Skeleton tree_skeleton(const PieceSet& set, const Tree& tree) {
  Forest one;
  one.trees.push_back(tree);
  const PiecesLayout layout = layout_forest(set, one);
  Skeleton s;
  std::vector<std::uint32_t> node_of_bone(tree.bones.size(), kNoParent);
  for (std::size_t b = 0; b < tree.bones.size(); ++b) {
    const Bone& bone = tree.bones[b];
    const Trs& w = layout.bone_world[b];
    if (bone.joint == 0 && bone.parent != kNone) {
      node_of_bone[b] = node_of_bone[bone.parent];  // the root joint sits on the parent's rim
      continue;
    }
    SkeletonNode n;
    n.position = w.t;
    n.radius = set.rim_radius * w.s;
    if (bone.parent != kNone) n.parent = node_of_bone[bone.parent];
    node_of_bone[b] = s.add(n);
  }
  return s;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t trees = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1000;
  const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
  const PieceSet set = bench::lower_bench_piece_set();
  Rng rng(seed);

  struct Encoding {
    const char* name;
    double seconds = 0;
    std::size_t bytes = 0;
  };
  std::vector<Encoding> enc = {
      {"canonical .glb"},          {"--flatten .glb"},
      {"--gpu-instancing .glb"},   {"instance buffer .bin"},
      {"mesh back end .glb"},      {"placed-pieces stream (.rmb section 12)"},
      {"  its tree records only"}, {"  whole .rmb with zstd"}};
  double assemble_s = 0, mesh_build_s = 0;
  std::size_t pieces = 0, bones = 0, mesh_triangles = 0, piece_triangles = 0;
  std::size_t min_pieces = SIZE_MAX, max_pieces = 0;
  for (std::size_t k = 0; k < trees; ++k) {
    const AssembleOptions ao = bench::bench_tree_options(rng, seed, k);
    auto t0 = std::chrono::steady_clock::now();
    Forest f;
    f.trees.push_back(assemble(set, ao));
    assemble_s += seconds_since(t0);
    const Tree& tree = f.trees[0];
    pieces += tree.pieces.size();
    bones += tree.bones.size();
    min_pieces = std::min(min_pieces, tree.pieces.size());
    max_pieces = std::max(max_pieces, tree.pieces.size());
    for (const PlacedPiece& p : tree.pieces)
      piece_triangles += 2 * set.types[p.type].lods[0].quads.size();
    const GltfEncoding modes[] = {GltfEncoding::kCanonical, GltfEncoding::kFlatten,
                                  GltfEncoding::kGpuInstancing};
    for (int e = 0; e < 3; ++e) {
      PiecesGltfOptions o;
      o.encoding = modes[e];
      t0 = std::chrono::steady_clock::now();
      const PiecesGltfBytes b = encode_pieces_gltf(set, f, o, true);
      enc[e].seconds += seconds_since(t0);
      enc[e].bytes += b.main.size();
    }
    t0 = std::chrono::steady_clock::now();
    const InstanceBufferBytes ib = encode_instance_buffer(set, f, "tree.bin", "tree.glb");
    enc[3].seconds += seconds_since(t0);
    enc[3].bytes += ib.binary.size() + ib.manifest.size();
    // The placed-pieces stream of the same tree: the whole section (set header with the piece
    // types, then the tree), its tree records alone, and a pieces-only .rmb with it compressed.
    t0 = std::chrono::steady_clock::now();
    const std::uint64_t tile_seed[] = {ao.seed};
    const RmbPieceStream stream = encode_piece_stream(set, f, tile_seed);
    rmb::Writer w;
    write_rmb_piece_stream(w, stream);
    enc[5].seconds += seconds_since(t0);
    enc[5].bytes += w.size();
    enc[6].bytes += rmb_piece_stream_tree_bytes(stream);
    RmbEncodeOptions zo;
    zo.zstd = true;
    enc[7].bytes += encode_rmb(ir::make_grammar(""), {}, {}, stream, zo).size();
    if (expand_piece_stream_binary(stream) != ib.binary) {
      std::fprintf(stderr, "bench_pieces: tree %zu: the stream's expansion differs\n", k);
      return 1;
    }
    t0 = std::chrono::steady_clock::now();
    const Skeleton s = tree_skeleton(set, tree);
    mesh::MeshOptions mo;
    mo.caps = true;
    const mesh::TreeMesh m = mesh::build_tree_mesh(s, mo);
    mesh_build_s += seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
    enc[4].bytes += mesh::encode_gltf({m}, true).main.size();
    enc[4].seconds += seconds_since(t0);
    mesh_triangles += m.triangle_count();
  }
  std::printf("trees: %zu, pieces: %zu (%zu..%zu per tree), bones: %zu\n", trees, pieces,
              min_pieces, max_pieces, bones);
  std::printf("assembly: %.3f s, %.0f pieces/s\n", assemble_s, double(pieces) / assemble_s);
  std::printf("piece triangles (LOD0, all instances): %zu; mesh back end triangles: %zu\n",
              piece_triangles, mesh_triangles);
  std::printf("mesh back end meshing: %.3f s, %.0f pieces/s equivalent\n", mesh_build_s,
              double(pieces) / mesh_build_s);
  std::printf(
      "| encoding | encode s | pieces/s (assembly + encode) | bytes | bytes/instance | bytes/tree "
      "|\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (std::size_t e = 0; e < enc.size(); ++e) {
    const double total = enc[e].seconds + (e == 4 ? mesh_build_s : assemble_s);
    if (e > 5) {  // parts of the stream's bytes, not encodings of their own
      std::printf("| %s | | | %zu | %.2f | %.0f |\n", enc[e].name, enc[e].bytes,
                  double(enc[e].bytes) / double(pieces), double(enc[e].bytes) / double(trees));
      continue;
    }
    std::printf("| %s | %.3f | %.0f | %zu | %.1f | %.0f |\n", enc[e].name, enc[e].seconds,
                double(pieces) / total, enc[e].bytes, double(enc[e].bytes) / double(pieces),
                double(enc[e].bytes) / double(trees));
  }
  return 0;
}
