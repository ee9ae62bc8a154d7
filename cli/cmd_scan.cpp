// ramus scan FILE -o OUT.ply|.xyz|.las|.laz [--from x,y,z]... [--noise S] [--density D]
//                 [--max-range R] [--beam-divergence MRAD] [--beam-diameter D]
//                 [--range-resolution R] [--registration-error S] [--leaves] [--truth OUT.json]
//                 [--seed S] [-n N] [-D name=value]...
// ramus scan FILE... --forest N|--layout L.json --area WxH -o OUT [--station-spacing D] ...
// Grows the grammar, meshes its tree and ray casts it from the scanner stations: a simulated
// terrestrial laser scan with a known skeleton, for testing reconstruction
// (docs/reconstruction.md). With --forest, a plot of N trees of the grammars on a ground plane
// scanned from a grid of stations, the truth holding every tree (docs/scale.md).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "mesh/tree_mesh.h"
#include "backends/scanner/forest.h"
#include "backends/scanner/scanner.h"
#include "cli/grow_args.h"
#include "cli/output_path.h"
#include "core/rng.h"
#include "core/skeleton_trees.h"
#include "formats/forest_layout.h"
#include "formats/las_file.h"
#include "formats/point_cloud_io.h"
#include "formats/skeleton_json.h"

namespace ramus::cli {
namespace {

struct ScanArgs {
  GrowArgs grow;
  std::vector<std::string> more_grammars;  // a forest's grammars after the first
  std::string output, truth;
  std::vector<std::string> from;
  double noise = 0.0, density = 2000.0, max_range = 0.0, angular_step_degrees = 0.0;
  double beam_divergence_mrad = 0.0, beam_diameter = 0.0, range_resolution = 0.0;
  double registration_error = 0.0;
  bool leaves = false;
  // Forest plots.
  int forest = 0;
  std::string area, layout;
  double station_spacing = 10.0;
  bool given_density = false, given_spacing = false, given_range_resolution = false;
};

// The beam and the registration (ScanOptions), the same for one tree and for a plot.
void set_beam(const ScanArgs& a, scanner::ScanOptions& o) {
  if (a.given_range_resolution && !(a.beam_divergence_mrad > 0 || a.beam_diameter > 0)) {
    throw UserError(
        "--range-resolution applies to a beam of some width: give --beam-divergence or "
        "--beam-diameter");
  }
  o.beam_divergence = a.beam_divergence_mrad * 1e-3;
  o.beam_diameter = a.beam_diameter;
  o.range_resolution = a.range_resolution;
  o.registration_error = a.registration_error;
}

void write_cloud(const std::string& path, const PointCloud& cloud) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".ply") {
    write_point_cloud_ply(path, cloud);
  } else if (ext == ".las" || ext == ".laz") {
    write_point_cloud_las(path, cloud);  // a .laz name writes the records compressed
  } else {
    write_point_cloud_xyz(path, cloud);
  }
}

// "WxH" in metres.
scanner::PlotArea parse_area(const std::string& text) {
  const auto x = text.find_first_of("xX");
  scanner::PlotArea a;
  try {
    std::size_t used = 0, used2 = 0;
    if (x == std::string::npos) throw std::invalid_argument(text);
    a.width = std::stod(text.substr(0, x), &used);
    a.depth = std::stod(text.substr(x + 1), &used2);
    if (used != x || used2 != text.size() - x - 1) throw std::invalid_argument(text);
  } catch (const std::exception&) {
    throw UserError("--area expects WIDTHxDEPTH in metres, e.g. 50x50, not '" + text + "'");
  }
  if (!(a.width > 0 && a.depth > 0 && std::isfinite(a.width) && std::isfinite(a.depth))) {
    throw UserError("--area: the width and depth must be positive, not '" + text + "'");
  }
  return a;
}

// Tree i of a random plot: grammar i mod count and its own seed, drawn from the plot's.
std::uint64_t tree_seed(std::uint64_t plot_seed, std::size_t i) {
  return Rng::stream(plot_seed, 0x74726565 /* "tree" */, i).next_u64() >> 40;
}

int run_forest_scan(const ScanArgs& a, const GlobalOptions& global) {
  if (!a.from.empty()) throw UserError("--from does not apply to --forest: stations form a grid");
  if (a.given_density) {
    throw UserError("--density does not apply to --forest: the stations' --angular-step sets it");
  }
  if (a.area.empty()) throw UserError("--forest and --layout need --area WIDTHxDEPTH");
  const scanner::PlotArea area = parse_area(a.area);
  std::vector<std::string> grammars{a.grow.file};
  grammars.insert(grammars.end(), a.more_grammars.begin(), a.more_grammars.end());
  const std::uint64_t plot_seed = a.grow.seed.value_or(1);
  std::vector<LayoutTree> layout;
  if (!a.layout.empty()) {
    try {
      layout = read_forest_layout(a.layout);
    } catch (const FormatError& e) {
      throw UserError(e.what());
    }
    if (a.forest > 0 && std::size_t(a.forest) != layout.size()) {
      throw UserError("--forest " + std::to_string(a.forest) + " but the layout has " +
                      std::to_string(layout.size()) + " trees");
    }
  } else {
    layout.resize(std::size_t(a.forest));
  }
  // Grow every tree (its grammar, its seed) at the origin first: placement needs the crowns.
  std::vector<Skeleton> trees;
  std::vector<double> radii;
  for (std::size_t i = 0; i < layout.size(); ++i) {
    const std::size_t g = layout[i].grammar.value_or(i % grammars.size());
    if (g >= grammars.size()) {
      throw UserError(a.layout + ": trees[" + std::to_string(i) + "].grammar is " +
                      std::to_string(g) + " but only " + std::to_string(grammars.size()) +
                      " grammar(s) were given");
    }
    GrowArgs grow = a.grow;
    grow.file = grammars[g];
    grow.seed = layout[i].seed.value_or(tree_seed(plot_seed, i));
    std::optional<Skeleton> s = grow_for_cli(grow);
    if (!s) return 1;
    if (s->roots().empty()) throw UserError(grammars[g] + ": the grammar grows no tree");
    radii.push_back(scanner::crown_radius(*s));
    trees.push_back(std::move(*s));
  }
  std::vector<Vec3> bases;
  if (a.layout.empty()) {
    try {
      bases = scanner::place_trees(radii, area, plot_seed);
    } catch (const scanner::ScanError& e) {
      throw UserError(e.what());
    }
  } else {
    for (const LayoutTree& t : layout) bases.push_back({t.x, t.y, 0});
  }
  for (std::size_t i = 0; i < trees.size(); ++i) {
    trees[i] = scanner::plant(trees[i], bases[i].x, bases[i].y);
  }
  scanner::ForestScanOptions fo;
  fo.station_spacing = a.station_spacing;
  fo.scan.noise = a.noise;
  fo.scan.max_range = a.max_range;
  fo.scan.leaves = a.leaves;
  fo.scan.seed = plot_seed;
  set_beam(a, fo.scan);
  fo.scan.angular_step = (a.angular_step_degrees > 0 ? a.angular_step_degrees : 0.1) * M_PI / 180;
  scanner::ScanResult r;
  try {
    r = scanner::scan_forest(trees, area, fo);
  } catch (const scanner::ScanError& e) {
    throw UserError(e.what());
  } catch (const mesh::MeshError& e) {
    throw UserError(e.what());
  }
  write_cloud(a.output, r.cloud);
  if (!a.truth.empty()) write_skeleton_json(a.truth, join_trees(trees));
  if (!global.quiet) {
    std::fprintf(stderr, "ramus: wrote %s (%zu trees, %zu points from %llu rays, %zu station(s))\n",
                 a.output.c_str(), trees.size(), r.cloud.size(),
                 static_cast<unsigned long long>(r.rays),
                 scanner::station_grid(area, bases, fo).size());
  }
  return 0;
}

int run_scan(const ScanArgs& a, const GlobalOptions& global) {
  if (a.forest > 0 || !a.layout.empty()) return run_forest_scan(a, global);
  if (!a.more_grammars.empty()) {
    throw UserError("several grammars need --forest N or --layout FILE (one tree is scanned)");
  }
  if (!a.area.empty() || a.given_spacing) {
    throw UserError("--area and --station-spacing apply to --forest and --layout only");
  }
  if (a.given_density && a.angular_step_degrees > 0) {
    throw UserError("give --density or --angular-step, not both");
  }
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
  o.angular_step = a.angular_step_degrees * M_PI / 180;
  o.seed = a.grow.seed.value_or(1);
  set_beam(a, o);
  if (o.registration_error > 0 && o.from.size() < 2) {
    throw UserError("--registration-error applies to scans from two or more --from stations");
  }
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
  write_cloud(a.output, r.cloud);
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
  CLI::App* sub = app.add_subcommand(
      "scan", "simulated laser scan of a grammar's tree (ground truth for tests)");
  add_grow_options(sub, args->grow);
  sub->add_option("more", args->more_grammars,
                  "more grammars of a --forest plot (tree i grows from grammar i mod count)");
  output_path(
      sub->add_option("-o,--output", args->output, "output point cloud: .ply, .xyz, .las or .laz"))
      ->required()
      ->check(CLI::Validator(
          [](const std::string& p) -> std::string {
            const std::string e = std::filesystem::path(p).extension().string();
            return e == ".ply" || e == ".xyz" || e == ".las" || e == ".laz"
                       ? ""
                       : "the output must end in .ply, .xyz, .las or .laz";
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
  sub->add_option("--angular-step", args->angular_step_degrees,
                  "degrees between rays (default: from --density; 0.1 with --forest)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--beam-divergence", args->beam_divergence_mrad,
                  "full angle of the beam in milliradians (0.3-0.5 for survey scanners; default "
                  "0: a line, no mixed returns at edges)")
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--beam-diameter", args->beam_diameter,
                  "width of the beam where it leaves the scanner (e.g. 0.007)")
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--range-resolution", args->range_resolution,
                  "surfaces in one footprint closer than this give one mixed echo (default 0: "
                  "every footprint gives one echo, as a phase-shift scanner)")
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--registration-error", args->registration_error,
                  "each station after the first shifted by this standard deviation per axis")
      ->check(CLI::NonNegativeNumber);
  sub->add_flag("--leaves", args->leaves, "scan the leaf cards too (default: wood only)");
  output_path(sub->add_option("--truth", args->truth,
                              "also write the skeleton as JSON (a forest: one root per tree)"));
  sub->add_option("--forest", args->forest,
                  "a plot of N trees of the grammars at random places, at least a crown radius "
                  "apart, on a ground plane (--seed seeds the plot)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--area", args->area, "the plot's WIDTHxDEPTH in metres (with --forest)");
  sub->add_option("--layout", args->layout,
                  "the plot's trees from JSON instead: {\"trees\": [{\"x\", \"y\", "
                  "\"grammar\", \"seed\"}]} (docs/scale.md)");
  sub->add_option("--station-spacing", args->station_spacing,
                  "stations on a grid of cells this wide (default 10; with --forest)")
      ->check(CLI::PositiveNumber);
  sub->callback([args, sub, &global, &run] {
    args->given_density = sub->count("--density") > 0;
    args->given_spacing = sub->count("--station-spacing") > 0;
    args->given_range_resolution = sub->count("--range-resolution") > 0;
    run = [args, &global] { return run_scan(*args, global); };
  });
}

}  // namespace ramus::cli
