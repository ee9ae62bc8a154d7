#include "cli/build_pieces.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include "backends/pieces/gltf_pieces.h"
#include "backends/pieces/output_instance_buffer.h"
#include "backends/pieces/output_layout.h"
#include "backends/pieces/output_piece_stream.h"
#include "backends/pieces/output_posed_mesh.h"
#include "backends/pieces/pieces.h"
#include "backends/preview/preview.h"
#include "backends/texture/bark_maps.h"
#include "cli/defines.h"
#include "cli/grow_args.h"
#include "cli/output_path.h"
#include "compiler/grow.h"
#include "core/atomic_file.h"
#include "grammar/check.h"
#include "grammar/loader.h"

namespace ramus::cli {
namespace {

// Copies of one tree stand on a row; the spacing keeps their crowns apart.
double row_spacing(const pieces::PieceSet& set, const pieces::Tree& tree) {
  pieces::Forest one;
  one.trees.push_back(tree);
  const pieces::PiecesLayout layout = pieces::layout_forest(set, one);
  double lo = 0, hi = 0;
  for (const Trs& w : layout.bone_world) {
    lo = std::min({lo, w.t.x, w.t.y});
    hi = std::max({hi, w.t.x, w.t.y});
  }
  return 1.2 * (hi - lo) + 4 * set.rim_radius;
}

// The skeleton a block without attach rules is fitted to: the lsystem its `skeleton` line names
// (in the root file or an import), else the root file's first or --system. The program is
// loaded and checked; only the lsystem block is lowered and grown. nullopt after printing the
// diagnostics of an error in the grammar.
std::optional<Skeleton> grow_named_skeleton(const Program& program, const GrowArgs& grow,
                                            const std::string& block, SourceManager& sources,
                                            DiagnosticSink& diags) {
  GrowOptions fit_options = to_grow_options(grow);
  const std::string named = pieces::pieces_skeleton_system(program, block);
  if (!named.empty()) {
    if (!grow.system.empty() && grow.system != named) {
      throw UserError("--system " + grow.system + ": the pieces block is fitted to the lsystem '" +
                      named + "' (its 'skeleton' setting)");
    }
    fit_options.system = named;
  }
  try {
    return grow_checked(program, fit_options, sources, diags);
  } catch (const GrowError& e) {
    print_diagnostics(sources, diags);
    if (!diags.has_errors()) throw UserError(e.what());
    return std::nullopt;
  }
}

}  // namespace

void add_pieces_build_options(CLI::App* sub, PiecesBuildArgs& a) {
  const char* group = "--target pieces";
  auto* flat =
      sub->add_flag("--flatten", a.flatten, "pieces: merge every piece into one mesh with one skin")
          ->group(group);
  sub->add_flag("--gpu-instancing", a.gpu_instancing,
                "pieces: EXT_mesh_gpu_instancing per piece type (_BONE_OFFSET, _TILE), no skins")
      ->group(group)
      ->excludes(flat);
  sub->add_option("--poses", a.poses,
                  "pieces: K trees of the same topology in K seeded poses (default 1)")
      ->check(CLI::Range(1, 100000))
      ->group(group);
  sub->add_flag("--wind", a.wind,
                "a looping wind animation (glTF): pieces: a clip of the bones; mesh: a skin along "
                "the branch chains")
      ->group(group);
  output_path(sub->add_option(
                  "--instance-buffer", a.instance_buffer,
                  "pieces: also write the engine instance buffer (.bin) and its .json manifest"))
      ->group(group);
  output_path(
      sub->add_option("--preview", a.preview, "pieces: also draw the posed trees (.png or .svg)"))
      ->group(group);
  sub->add_option("--pieces", a.block, "pieces: the pieces block (default: the first)")
      ->group(group);
}

std::optional<GrownPieces> grow_pieces(const GrowArgs& grow, const PiecesBuildArgs& a) {
  // An .rmb holds the pieces blocks with their numbers folded (-D is refused) and the lsystem a
  // block without attach rules is fitted to; the source is loaded and checked.
  const bool binary = is_binary_grammar(grow.file);
  const GrowOptions grow_options = to_grow_options(grow);
  SourceManager sources;
  DiagnosticSink diags;
  pieces::LowerPiecesOptions lo;
  lo.block = a.block;
  lo.defines = grow_options.defines;
  const Program program = binary ? load_binary_pieces(grow, sources, diags, lo.mesh_files)
                                 : load_program(grow.file, sources, diags);
  CheckOptions check_options;
  check_options.defines = grow_options.defines;
  if (!diags.has_errors()) check_program(program, sources, diags, check_options);
  if (diags.has_errors()) {
    print_diagnostics(sources, diags);
    return std::nullopt;
  }
  const std::uint64_t seed = grow.seed.value_or(1);
  GrownPieces out;
  try {
    out.set = pieces::lower_pieces(program, sources, lo, diags);
    if (diags.has_errors()) {
      print_diagnostics(sources, diags);
      return std::nullopt;
    }
    pieces::Tree tree;
    if (pieces::pieces_block_fits_skeleton(program, a.block)) {
      std::optional<Skeleton> skeleton =
          binary ? grow_for_cli(grow) : grow_named_skeleton(program, grow, a.block, sources, diags);
      if (!skeleton) return std::nullopt;
      pieces::FitOptions fo;
      fo.seed = seed;
      tree = pieces::fit_skeleton(out.set, *skeleton, fo);
    } else {
      pieces::AssembleOptions ao;
      ao.seed = seed;
      tree = pieces::assemble(out.set, ao);
    }
    print_diagnostics(sources, diags);
    out.forest = pieces::pose_copies(out.set, tree, a.poses, seed, row_spacing(out.set, tree));
    // Copy k's tiles are drawn with seed + k (pose_copies); every output shows the poses as the
    // placed-pieces stream stores them (backends/pieces/output_piece_stream.h).
    std::vector<std::uint64_t> tile_seeds;
    for (std::size_t k = 0; k < out.forest.trees.size(); ++k) tile_seeds.push_back(seed + k);
    out.stream = pieces::quantize_forest_poses(out.set, out.forest, tile_seeds);
  } catch (const pieces::PiecesError& e) {
    print_diagnostics(sources, diags);
    throw UserError(e.what());
  }
  return out;
}

int build_pieces(const GrowArgs& grow, const PiecesBuildArgs& a, const std::string& output,
                 bool quiet) {
  const std::string ext = std::filesystem::path(output).extension().string();
  if (ext != ".glb" && ext != ".gltf") {
    throw UserError("--target pieces writes a .glb or .gltf file, not " + output);
  }
  if (!a.preview.empty()) {
    const std::string pe = std::filesystem::path(a.preview).extension().string();
    if (pe != ".png" && pe != ".svg") throw UserError("--preview must end in .png or .svg");
  }
  std::optional<GrownPieces> grown = grow_pieces(grow, a);
  if (!grown) return 1;
  const pieces::PieceSet& set = grown->set;
  const pieces::Forest& forest = grown->forest;
  try {
    if (a.lod < 0 || std::size_t(a.lod) >= set.lod_segments.size()) {
      throw UserError("--lod " + std::to_string(a.lod) + ": the pieces are built at " +
                      std::to_string(set.lod_segments.size()) + " levels (0.." +
                      std::to_string(set.lod_segments.size() - 1) + ")");
    }
    pieces::PiecesGltfOptions go;
    go.encoding = a.flatten          ? pieces::GltfEncoding::kFlatten
                  : a.gpu_instancing ? pieces::GltfEncoding::kGpuInstancing
                                     : pieces::GltfEncoding::kCanonical;
    go.lod = std::size_t(a.lod);
    go.wind = a.wind;
    const std::uint64_t seed = grow.seed.value_or(1);
    go.wind_options.seed = seed;
    go.seed = seed;
    if (!a.bark.empty()) {
      try {
        go.bark = std::make_shared<const texture::TileAtlas>(texture::bark_atlas(
            texture::tile_set_from_atlas(texture::read_image(a.bark), a.bark_edges)));
      } catch (const texture::ImageError& e) {
        throw UserError(e.what());
      } catch (const std::invalid_argument& e) {
        throw UserError("--bark " + a.bark + ": " + e.what());
      }
    }
    go.name = set.name.empty() ? std::filesystem::path(grow.file).stem().string() : set.name;
    pieces::write_pieces_gltf(set, forest, go, output);
    std::string manifest;
    if (!a.instance_buffer.empty()) {
      manifest = pieces::write_instance_buffer(
          set, forest, a.instance_buffer,
          a.flatten ? "" : std::filesystem::path(output).filename().string());
    }
    if (!a.preview.empty()) {
      const mesh::TreeMesh posed =
          pieces::posed_forest_mesh(set, forest, set.lod_segments.size() - 1, seed);
      preview::write_preview(posed, a.preview, preview::PreviewOptions{});
    }
    if (!quiet) {
      std::size_t placed = 0, bones = 0;
      for (const pieces::Tree& t : forest.trees) {
        placed += t.pieces.size();
        bones += t.bones.size();
      }
      std::fprintf(stderr, "ramus: wrote %s (%zu trees, %zu pieces, %zu bones)\n", output.c_str(),
                   forest.trees.size(), placed, bones);
      if (!manifest.empty())
        std::fprintf(stderr, "ramus: wrote %s and %s\n", a.instance_buffer.c_str(),
                     manifest.c_str());
      if (!a.preview.empty()) std::fprintf(stderr, "ramus: wrote %s\n", a.preview.c_str());
    }
  } catch (const pieces::PiecesError& e) {
    throw UserError(e.what());
  } catch (const mesh::MeshError& e) {
    throw UserError(e.what());
  } catch (const std::invalid_argument& e) {
    throw UserError(e.what());
  }
  return 0;
}

}  // namespace ramus::cli
