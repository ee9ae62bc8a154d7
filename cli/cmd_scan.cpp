// ramus scan FILE -o OUT.ply|.xyz [--from x,y,z]... [--noise S] [--density D] [--max-range R]
//                 [--leaves] [--truth OUT.json] [--seed S] [-n N] [-D name=value]...
// Grows the grammar, meshes its tree and ray casts it from the scanner stations: a simulated
// terrestrial laser scan with a known skeleton, for testing reconstruction (docs/reconstruction.md).
#include <cstdio>
#include <filesystem>
#include <memory>

#include "backends/mesh/tree_mesh.h"
#include "backends/scanner/scanner.h"
#include "cli/grow_args.h"
#include "cli/output_path.h"
#include "formats/point_cloud_io.h"
#include "formats/skeleton_json.h"

namespace ramus::cli {
namespace {

struct ScanArgs {
  GrowArgs grow;
  std::string output, truth;
  std::vector<std::string> from;
  double noise = 0.0, density = 2000.0, max_range = 0.0;
  bool leaves = false;
};

int run_scan(const ScanArgs& a, const GlobalOptions& global) {
  scanner::ScanOptions o;
  try {
    for (const std::string& f : a.from) o.from.push_back(scanner::parse_position(f));
  } catch (const scanner::ScanError& e) {
    throw UserError(std::string("--from: ") + e.what());
  }
  o.noise = a.noise;
  o.density = a.density;
  o.max_range = a.max_range;
  o.leaves = a.leaves;
  o.seed = a.grow.seed.value_or(1);
  const std::optional<Skeleton> skeleton = grow_for_cli(a.grow);
  if (!skeleton) return 1;
  scanner::ScanResult r;
  try {
    r = scanner::scan_skeleton(*skeleton, o);
  } catch (const scanner::ScanError& e) {
    throw UserError(e.what());
  } catch (const mesh::MeshError& e) {
    throw UserError(e.what());
  }
  r.cloud.source = a.grow.file;
  const std::string ext = std::filesystem::path(a.output).extension().string();
  if (ext == ".ply") {
    write_point_cloud_ply(a.output, r.cloud);
  } else {
    write_point_cloud_xyz(a.output, r.cloud);
  }
  if (!a.truth.empty()) write_skeleton_json(a.truth, *skeleton);
  if (!global.quiet) {
    std::fprintf(stderr, "ramus: wrote %s (%zu points from %llu rays, %zu station(s))\n",
                 a.output.c_str(), r.cloud.size(), static_cast<unsigned long long>(r.rays),
                 o.from.empty() ? std::size_t(1) : o.from.size());
  }
  return 0;
}

}  // namespace

void add_scan(CLI::App& app, const GlobalOptions& global, std::function<int()>& run) {
  auto args = std::make_shared<ScanArgs>();
  CLI::App* sub =
      app.add_subcommand("scan", "simulated laser scan of a grammar's tree (ground truth for tests)");
  add_grow_options(sub, args->grow);
  output_path(sub->add_option("-o,--output", args->output, "output point cloud: .ply or .xyz"))
      ->required()
      ->check(CLI::Validator(
          [](const std::string& p) -> std::string {
            const std::string e = std::filesystem::path(p).extension().string();
            return e == ".ply" || e == ".xyz" ? "" : "the output must end in .ply or .xyz";
          },
          "FILE", "point cloud file"));
  sub->add_option("--from", args->from,
                  "scanner station x,y,z (repeatable; default: one station 1.5 heights away)");
  sub->add_option("--noise", args->noise, "standard deviation of the range noise")
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--density", args->density,
                  "points per unit area facing the station at the tree's distance (default 2000)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--max-range", args->max_range, "returns beyond this range are lost")
      ->check(CLI::NonNegativeNumber);
  sub->add_flag("--leaves", args->leaves, "scan the leaf cards too (default: wood only)");
  output_path(sub->add_option("--truth", args->truth, "also write the tree's skeleton as JSON"));
  sub->callback([args, &global, &run] { run = [args, &global] { return run_scan(*args, global); }; });
}

}  // namespace ramus::cli
