// ramus preview FILE -o OUT.png|.svg [--size WxH] [-n N] [--seed S] [-D name=value]...
//                    [--system NAME] [--pipe-exponent E]
// A picture from the front and from the side (docs/mesh.md, "Preview") of what FILE holds: a
// grammar (.ramus, or an .rmb decoded as the runtime decodes it) grown into its tree, a skeleton
// (.json) meshed as `ramus build` meshes it, a mesh (.glb .gltf .obj .ply) as the file has it, or a
// scan (.ply .xyz .txt .asc .csv .las .laz .pcd) as points. Options that cannot apply to FILE's kind are
// errors rather than silently ignored, so a user who asks for a seed learns it changed nothing.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "backends/mesh/mesh_reader.h"
#include "mesh/tree_mesh.h"
#include "backends/preview/point_preview.h"
#include "backends/preview/preview.h"
#include "cli/grow_args.h"
#include "cli/output_path.h"
#include "cli/preview_input.h"
#include "cli/read_file.h"
#include "formats/point_cloud_io.h"
#include "formats/rmb/rmb.h"
#include "formats/skeleton_json.h"

namespace ramus::cli {
namespace {

struct PreviewArgs {
  GrowArgs grow;
  std::string output;
  std::string size = "1200x800";
  double pipe_exponent = 0;
  CLI::App* command = nullptr;  // to ask which options were given
};

bool parse_size(const std::string& s, int& w, int& h) {
  char x = 0, extra = 0;
  return std::sscanf(s.c_str(), "%d%c%d%c", &w, &x, &h, &extra) == 3 && (x == 'x' || x == 'X');
}

// Refuses the options that mean nothing for this kind of input: the grow options for anything
// but a grammar, --pipe-exponent for what is not meshed from a skeleton here.
void check_options(const PreviewArgs& a, PreviewInput kind) {
  const bool grammar = kind == PreviewInput::kGrammar || kind == PreviewInput::kBinaryGrammar;
  const bool skeleton = grammar || kind == PreviewInput::kSkeleton;
  const std::pair<const char*, const char*> grow_options[] = {{"--steps", "-n/--steps"},
                                                              {"--seed", "--seed"},
                                                              {"--define", "-D/--define"},
                                                              {"--system", "--system"},
                                                              {"--max-modules", "--max-modules"},
                                                              {"--max-memory", "--max-memory"}};
  for (const auto& [name, shown] : grow_options) {
    if (!grammar && a.command->count(name) > 0) {
      throw UserError(std::string(shown) + " applies to grammars only; " + a.grow.file + " is a " +
                      preview_input_name(kind));
    }
  }
  if (!skeleton && a.command->count("--pipe-exponent") > 0) {
    throw UserError("--pipe-exponent applies to grammars and skeletons only; " + a.grow.file +
                    " is a " + preview_input_name(kind));
  }
}

// The tree mesh of a grown or read skeleton, as `ramus build` makes LOD0.
mesh::TreeMesh mesh_skeleton(const Skeleton& skeleton, const PreviewArgs& a, bool svg) {
  mesh::MeshOptions o;
  o.pipe_exponent = a.pipe_exponent;
  if (svg) o.max_radial_segments = 6;  // polygons, not pixels: keep the file small
  mesh::MeshReport report;
  mesh::TreeMesh m = mesh::build_tree_mesh(skeleton, o, 0, &report);
  for (const std::string& w : report.warnings())
    std::fprintf(stderr, "ramus: warning: %s\n", w.c_str());
  return m;
}

int run_preview(const PreviewArgs& a, const GlobalOptions& global) {
  preview::PreviewOptions po;
  if (!parse_size(a.size, po.width, po.height)) {
    throw UserError("--size must look like 1200x800, not '" + a.size + "'");
  }
  const PreviewInput kind = classify_preview_input(a.grow.file);
  check_options(a, kind);
  const bool svg = std::filesystem::path(a.output).extension() == ".svg";
  try {
    if (kind == PreviewInput::kScan) {
      const PointCloud cloud = read_point_cloud(a.grow.file);
      preview::write_points_preview(cloud, a.output, po);
    } else {
      mesh::TreeMesh m;
      if (kind == PreviewInput::kMesh) {
        m = mesh::read_mesh_file(a.grow.file);
        po.cull_back_faces = false;  // not ours: may be open or wound either way
      } else {
        std::optional<Skeleton> skeleton;
        if (kind == PreviewInput::kSkeleton) {
          skeleton = read_skeleton_json(a.grow.file);
        } else {
          skeleton = grow_for_cli(a.grow);  // a .ramus, or an .rmb as the runtime derives it
          if (!skeleton) return 1;
        }
        m = mesh_skeleton(*skeleton, a, svg);
      }
      if (m.triangle_count() == 0) throw UserError("the tree has no geometry to draw");
      preview::write_preview(m, a.output, po);
    }
  } catch (const FormatError& e) {
    throw UserError(e.what());
  } catch (const mesh::MeshError& e) {
    throw UserError(e.what());
  } catch (const std::invalid_argument& e) {
    throw UserError(e.what());
  }
  if (!global.quiet) std::fprintf(stderr, "ramus: wrote %s\n", a.output.c_str());
  return 0;
}

}  // namespace

void add_preview(CLI::App& app, const GlobalOptions& global, std::function<int()>& run) {
  auto args = std::make_shared<PreviewArgs>();
  CLI::App* sub = app.add_subcommand(
      "preview",
      "draw a grammar's tree, a skeleton, a mesh or a scan (front and side) as PNG or SVG");
  args->command = sub;
  add_grow_options(sub, args->grow);
  sub->get_option("file")->description(
      "what to draw: a grammar (.ramus .rmb), a skeleton (.json), a mesh (.glb .gltf .obj .ply) "
      "or a scan (.ply .xyz .txt .asc .csv .las .laz .pcd); a .ply with faces is a mesh");
  output_path(sub->add_option("-o,--output", args->output, "output picture: .png or .svg"))
      ->required()
      ->check(CLI::Validator(
          [](const std::string& p) -> std::string {
            const auto e = std::filesystem::path(p).extension();
            return e == ".png" || e == ".svg" ? "" : "the output must end in .png or .svg";
          },
          "FILE", "picture"));
  sub->add_option("--size", args->size, "picture size WxH (default 1200x800)");
  sub->add_option("--pipe-exponent", args->pipe_exponent,
                  "radii by the pipe model (see build); grammars and skeletons")
      ->check(CLI::Range(1.0, 10.0));
  sub->callback(
      [args, &global, &run] { run = [args, &global] { return run_preview(*args, global); }; });
}

}  // namespace ramus::cli
