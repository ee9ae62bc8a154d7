// ramus build FILE -o OUT.glb|.gltf|.obj|.ply [--target mesh] [--lod N] [--lod-files] [--up y|z]
//                  [--seed S] [-n N] [-D name=value]... [--system NAME] [--pipe-exponent E]
//                  [--leaves quad|crossed] [--leaf-scale K] [--wind] [--compress draco|meshopt]
// Grows the grammar and writes its tree as a mesh (docs/mesh.md). glTF gets the levels of
// detail LOD0..LOD N as separate meshes switched by MSFT_lod; OBJ and PLY hold one mesh, level N.
// --lod-files writes OUT_LOD0 .. OUT_LODN instead, one level per file, for engines without
// MSFT_lod. --wind adds the wind skin and its looping animation (glTF only), --compress
// compresses the glTF's geometry (backends/mesh/gltf_compress.h).
// --target pieces writes skinned piece instances instead (build_pieces.h, docs/pieces.md).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "backends/mesh/gltf_writer.h"
#include "backends/mesh/openmesh_writer.h"
#include "backends/texture/bark_maps.h"
#include "cli/build_binary.h"
#include "cli/build_pieces.h"
#include "cli/grow_args.h"
#include "cli/mesh_output.h"
#include "cli/output_path.h"
#include "mesh/tree_mesh.h"

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
  std::string compress;  // --compress: "", "draco" or "meshopt"
  std::string bark;      // --bark: a tile set atlas; empty for the bundled set
  int bark_edges = 2;
  std::vector<std::string> given;  // the options the command line gave
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

// The options each target reads; any other given with it is a mistake, not silently ignored.
const std::vector<std::string>& target_options(const std::string& target) {
  static const std::vector<std::string> mesh = {
      "--lod",        "--lod-files", "--up",       "--pipe-exponent", "--leaves",
      "--leaf-scale", "--wind",      "--compress", "--bark",          "--bark-edges"};
  static const std::vector<std::string> pieces = {
      "--lod",     "--flatten", "--gpu-instancing", "--poses",     "--wind", "--instance-buffer",
      "--preview", "--pieces",  "--bark",           "--bark-edges"};
  static const std::vector<std::string> binary = {
      "--tolerance",  "--zstd",          "--strip",  "--rmb-version",
      "--mesh-paths", "--placed-pieces", "--pieces", "--poses"};
  return target == "pieces" ? pieces : target == "binary" ? binary : mesh;
}

// Every target-specific option on the command line, for check_target_options.
const std::vector<std::string>& all_target_options() {
  static const std::vector<std::string> all = [] {
    std::vector<std::string> v;
    for (const char* t : {"mesh", "pieces", "binary"})
      for (const std::string& o : target_options(t))
        if (std::find(v.begin(), v.end(), o) == v.end()) v.push_back(o);
    return v;
  }();
  return all;
}

void check_target_options(const BuildArgs& a, bool gltf) {
  const auto& mine = target_options(a.target);
  for (const std::string& o : a.given) {
    if (std::find(mine.begin(), mine.end(), o) != mine.end()) continue;
    std::string targets;
    for (const char* t : {"mesh", "pieces", "binary"}) {
      const auto& theirs = target_options(t);
      if (std::find(theirs.begin(), theirs.end(), o) == theirs.end()) continue;
      targets += (targets.empty() ? "" : " and ") + std::string(t);
    }
    throw UserError(o + " applies to --target " + targets + " only");
  }
  if (a.target != "mesh" || gltf) return;
  // OBJ and PLY have neither animation nor a compressed form.
  if (a.pieces.wind)
    throw UserError(
        "--wind needs a glTF output (.glb or .gltf): OBJ and PLY "
        "have no animation");
  if (!a.compress.empty()) throw UserError("--compress needs a glTF output (.glb or .gltf)");
}

mesh::GltfCompression compression(const std::string& name) {
  return name == "draco"     ? mesh::GltfCompression::kDraco
         : name == "meshopt" ? mesh::GltfCompression::kMeshopt
                             : mesh::GltfCompression::kNone;
}

// Writes the levels, each to its own file (--lod-files) or together; returns the triangles of
// the finest level written.
std::size_t write_levels(const std::vector<mesh::TreeMesh>& lods, const BuildArgs& a,
                         mesh::UpAxis up, bool gltf, const texture::BarkTextures* bark) {
  if (a.lod_files) {
    for (std::size_t k = 0; k < lods.size(); ++k) {
      const std::string path = lod_file_path(a.output, int(k));
      if (gltf) {
        mesh::write_gltf({lods[k]}, path, compression(a.compress), bark);
      } else {
        mesh::write_openmesh(lods[k], path, up, bark);
      }
    }
  } else if (gltf) {
    mesh::write_gltf(lods, a.output, compression(a.compress), bark);
  } else {
    mesh::write_openmesh(lods.back(), a.output, up, bark);
  }
  return gltf || a.lod_files ? lods.front().triangle_count() : lods.back().triangle_count();
}

// The bark textures of the tile set atlas --bark names (docs/textures.md).
texture::BarkTextures bark_textures_of(const BuildArgs& a) {
  try {
    return texture::bark_textures(
        texture::tile_set_from_atlas(texture::read_image(a.bark), a.bark_edges));
  } catch (const texture::ImageError& e) {
    throw UserError(e.what());
  } catch (const std::invalid_argument& e) {
    throw UserError("--bark " + a.bark + ": " + e.what());
  }
}

int run_build(const BuildArgs& a, const GlobalOptions& global) {
  const std::string out_ext = extension(a.output);
  check_target_options(a, out_ext == ".glb" || out_ext == ".gltf");
  if (a.target == "binary") return build_binary(a.grow, a.binary, a.pieces, a.output, global.quiet);
  if (a.target == "pieces") {
    PiecesBuildArgs p = a.pieces;
    p.lod = a.lod;
    p.bark = a.bark;
    p.bark_edges = a.bark_edges;
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
  o.wind = a.pieces.wind;
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
    std::optional<texture::BarkTextures> bark;
    if (!a.bark.empty()) bark = bark_textures_of(a);
    if (o.wind && lods.front().wind_rig.animated_joints() == 0)
      throw UserError("--wind: the tree has no branch long enough to sway");
    triangles = write_levels(lods, a, up, gltf, bark ? &*bark : nullptr);
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
  sub->add_option("--compress", args->compress,
                  "glTF: compress the geometry with draco (KHR_draco_mesh_compression) or "
                  "meshopt (EXT_meshopt_compression, KHR_mesh_quantization); see docs/mesh.md")
      ->check(CLI::IsMember({"draco", "meshopt"}));
  sub->add_option("--bark", args->bark,
                  "the bark's tile set atlas (.png from `ramus tiles`; default the bundled "
                  "procedural bark): base colour and a normal map from it (--target pieces: "
                  "a tile per quad), see docs/textures.md")
      ->check(CLI::ExistingFile);
  sub->add_option("--bark-edges", args->bark_edges,
                  "edge colours K of the --bark atlas (1, 2 or 4; default 2)")
      ->check(CLI::IsMember({1, 2, 4}));
  add_pieces_build_options(sub, args->pieces);
  add_binary_build_options(sub, args->binary);
  sub->callback([args, sub, &global, &run] {
    for (const std::string& o : all_target_options())
      if (sub->count(o) > 0) args->given.push_back(o);
    run = [args, &global] { return run_build(*args, global); };
  });
}

}  // namespace ramus::cli
