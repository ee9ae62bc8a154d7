// ramus build FILE -o OUT.glb|.gltf|.obj|.ply [--target mesh] [--lod N] [--lod-files] [--up y|z]
//                  [--seed S] [-n N] [-D name=value]... [--system NAME] [--pipe-exponent E]
//                  [--leaves quad|crossed] [--leaf-scale K]
// Grows the grammar and writes its tree as a mesh (docs/mesh.md). glTF gets the levels of
// detail LOD0..LOD N as separate meshes switched by MSFT_lod; OBJ and PLY hold one mesh, level N.
// --lod-files writes OUT_LOD0 .. OUT_LODN instead, one level per file, for engines without
// MSFT_lod.
// --target pieces writes skinned piece instances instead (build_pieces.h, docs/pieces.md).
#include <cstdio>
#include <filesystem>
#include <memory>

#include "backends/mesh/gltf_writer.h"
#include "backends/mesh/openmesh_writer.h"
#include "backends/mesh/tree_mesh.h"
#include "cli/build_binary.h"
#include "cli/build_pieces.h"
#include "cli/grow_args.h"
#include "cli/mesh_output.h"
#include "cli/output_path.h"

namespace ramus::cli {
namespace {

struct BuildArgs {
  GrowArgs grow;
  std::string output;
  std::string target = "mesh";
  int lod = 0;
  bool lod_files = false;
  std::string up;  // --up: empty for the format's default
  double pipe_exponent = 0;
  std::string leaves = "quad";
  double leaf_scale = 1;
  PiecesBuildArgs pieces;
  BinaryBuildArgs binary;
};

std::string extension(const std::string& path) {
  return std::filesystem::path(path).extension().string();
}

void print_warnings(const mesh::MeshReport& report) {
  for (const std::string& w : report.warnings())
    std::fprintf(stderr, "ramus: warning: %s\n", w.c_str());
}

// Options of the mesh target given with another target are mistakes, not silently ignored.
void check_mesh_only_options(const BuildArgs& a) {
  if (a.target == "mesh") return;
  if (!a.up.empty()) throw UserError("--up applies to --target mesh only");
  if (a.lod_files) throw UserError("--lod-files applies to --target mesh only");
}

// Writes the levels, each to its own file (--lod-files) or together; returns the triangles of
// the finest level written.
std::size_t write_levels(const std::vector<mesh::TreeMesh>& lods, const BuildArgs& a,
                         mesh::UpAxis up, bool gltf) {
  if (a.lod_files) {
    for (std::size_t k = 0; k < lods.size(); ++k) {
      const std::string path = lod_file_path(a.output, int(k));
      if (gltf) {
        mesh::write_gltf({lods[k]}, path);
      } else {
        mesh::write_openmesh(lods[k], path, up);
      }
    }
  } else if (gltf) {
    mesh::write_gltf(lods, a.output);
  } else {
    mesh::write_openmesh(lods.back(), a.output, up);
  }
  return gltf || a.lod_files ? lods.front().triangle_count() : lods.back().triangle_count();
}

int run_build(const BuildArgs& a, const GlobalOptions& global) {
  check_mesh_only_options(a);
  if (a.target == "binary") return build_binary(a.grow, a.binary, a.output, global.quiet);
  if (a.target == "pieces") {
    PiecesBuildArgs p = a.pieces;
    p.lod = a.lod;
    return build_pieces(a.grow, p, a.output, global.quiet);
  }
  if (extension(a.output) == ".rmb") throw UserError("an .rmb output needs --target binary");
  if (a.lod_files && a.lod == 0) throw UserError("--lod-files needs --lod N with N >= 1");
  const std::string ext = extension(a.output);
  const bool gltf = ext == ".glb" || ext == ".gltf";
  const mesh::UpAxis up = mesh_up_axis(a.up, a.output);
  const std::optional<Skeleton> skeleton = grow_for_cli(a.grow);
  if (!skeleton) return 1;
  mesh::MeshOptions o;
  o.name = std::filesystem::path(a.grow.file).stem().string();
  o.pipe_exponent = a.pipe_exponent;
  o.leaf_style = a.leaves == "crossed" ? mesh::LeafStyle::kCrossed : mesh::LeafStyle::kQuad;
  o.leaf_scale = a.leaf_scale;
  mesh::MeshReport report;
  std::size_t triangles = 0;
  try {
    std::vector<mesh::TreeMesh> lods;
    if (gltf || a.lod_files) {
      o.lod_count = a.lod + 1;
      lods = mesh::build_tree_lods(*skeleton, o, &report);
    } else {
      lods.push_back(mesh::build_tree_mesh(*skeleton, o, a.lod, &report));
    }
    print_warnings(report);
    triangles = write_levels(lods, a, up, gltf);
  } catch (const mesh::MeshError& e) {
    throw UserError(e.what());
  }
  if (!global.quiet) {
    std::fprintf(stderr, "ramus: wrote %s (%zu nodes, %zu organs, %zu triangles at LOD%d)\n",
                 a.lod_files ? lod_file_path(a.output, 0).c_str() : a.output.c_str(),
                 skeleton->size(), skeleton->organs.size(), triangles,
                 gltf || a.lod_files ? 0 : a.lod);
  }
  return 0;
}

}  // namespace

void add_build(CLI::App& app, const GlobalOptions& global, std::function<int()>& run) {
  auto args = std::make_shared<BuildArgs>();
  CLI::App* sub = app.add_subcommand("build", "compile a grammar into an asset (a tree mesh)");
  add_grow_options(sub, args->grow);
  output_path(sub->add_option(
                  "-o,--output", args->output,
                  "output: .glb, .gltf (+ .bin), .obj (+ .mtl), .ply; .rmb with --target binary"))
      ->required()
      ->check(CLI::Validator(
          [](const std::string& p) -> std::string {
            const std::string e = extension(p);
            return e == ".glb" || e == ".gltf" || e == ".obj" || e == ".ply" || e == ".rmb"
                       ? ""
                       : "the output must end in .glb, .gltf, .obj, .ply or .rmb";
          },
          "FILE", "mesh file"));
  // The targets later back ends add (pieces, binary, voxels) join this list.
  sub->add_option("--target", args->target, "what to build (default: mesh)")
      ->check(CLI::IsMember({"mesh", "binary", "pieces"}));
  sub->add_option("--lod", args->lod,
                  "levels of detail: glTF gets LOD0..LOD N, OBJ/PLY level N; "
                  "--target pieces: the tessellation level the pieces are written at")
      ->check(CLI::Range(0, 7));
  sub->add_flag("--lod-files", args->lod_files,
                "write each level LOD0..LOD N to its own file OUT_LODk.ext (for engines without "
                "glTF's MSFT_lod); needs --lod N >= 1");
  add_up_option(sub, args->up);
  sub->add_option("--pipe-exponent", args->pipe_exponent,
                  "radii by the pipe model r^e = sum r_child^e (2 da Vinci, 2.5 Livny); "
                  "default: the turtle's widths")
      ->check(CLI::Range(1.0, 10.0));
  sub->add_option("--leaves", args->leaves, "leaf cards: quad or crossed")
      ->check(CLI::IsMember({"quad", "crossed"}));
  sub->add_option("--leaf-scale", args->leaf_scale, "leaf length per unit of organ size")
      ->check(CLI::PositiveNumber);
  add_pieces_build_options(sub, args->pieces);
  add_binary_build_options(sub, args->binary);
  sub->callback(
      [args, &global, &run] { run = [args, &global] { return run_build(*args, global); }; });
}

}  // namespace ramus::cli
