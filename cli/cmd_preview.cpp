// ramus preview FILE -o OUT.png|.svg [--size WxH] [-n N] [--seed S] [-D name=value]...
//                    [--system NAME] [--pipe-exponent E]
// A picture of the grammar's tree from the front and from the side (docs/mesh.md, "Preview").
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "backends/mesh/tree_mesh.h"
#include "backends/preview/preview.h"
#include "cli/grow_args.h"
#include "cli/output_path.h"

namespace ramus::cli {
namespace {

struct PreviewArgs {
  GrowArgs grow;
  std::string output;
  std::string size = "1200x800";
  double pipe_exponent = 0;
};

bool parse_size(const std::string& s, int& w, int& h) {
  char x = 0, extra = 0;
  return std::sscanf(s.c_str(), "%d%c%d%c", &w, &x, &h, &extra) == 3 && (x == 'x' || x == 'X');
}

int run_preview(const PreviewArgs& a, const GlobalOptions& global) {
  preview::PreviewOptions po;
  if (!parse_size(a.size, po.width, po.height)) {
    throw UserError("--size must look like 1200x800, not '" + a.size + "'");
  }
  const std::optional<Skeleton> skeleton = grow_for_cli(a.grow);
  if (!skeleton) return 1;
  mesh::MeshOptions o;
  o.pipe_exponent = a.pipe_exponent;
  const bool svg = std::filesystem::path(a.output).extension() == ".svg";
  if (svg) o.max_radial_segments = 6;  // polygons, not pixels: keep the file small
  try {
    mesh::MeshReport report;
    const mesh::TreeMesh m = mesh::build_tree_mesh(*skeleton, o, 0, &report);
    for (const std::string& w : report.warnings())
      std::fprintf(stderr, "ramus: warning: %s\n", w.c_str());
    if (m.triangle_count() == 0) throw UserError("the tree has no geometry to draw");
    preview::write_preview(m, a.output, po);
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
  CLI::App* sub =
      app.add_subcommand("preview", "draw a grammar's tree (front and side) as PNG or SVG");
  add_grow_options(sub, args->grow);
  output_path(sub->add_option("-o,--output", args->output, "output picture: .png or .svg"))
      ->required()
      ->check(CLI::Validator(
          [](const std::string& p) -> std::string {
            const auto e = std::filesystem::path(p).extension();
            return e == ".png" || e == ".svg" ? "" : "the output must end in .png or .svg";
          },
          "FILE", "picture"));
  sub->add_option("--size", args->size, "picture size WxH (default 1200x800)");
  sub->add_option("--pipe-exponent", args->pipe_exponent, "radii by the pipe model (see build)")
      ->check(CLI::Range(1.0, 10.0));
  sub->callback(
      [args, &global, &run] { run = [args, &global] { return run_preview(*args, global); }; });
}

}  // namespace ramus::cli
