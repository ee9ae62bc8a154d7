// ramus enhance SCAN -o OUT.ply|.xyz [--grid 64] [--seed 1] [--classes 17] [--scanner x,y,z]
// Super-resolution of a scan with its own voxel grammar (Friedman & Stamos 2013, III-C/III-D):
// the scan is aligned and voxelized at --grid, a voxel grammar is learned from its nonstandard
// Haar pyramid, the grammar synthesizes the wavelets of one more level, and the inverse transform
// gives a grid of twice the side. Writes the centres of the occupied voxels (world coordinates)
// and prints how the result and plain upsampling compare with the scan voxelized at twice the side.
#include <cstdio>
#include <memory>
#include <string>

#include "compiler/driver/command.h"
#include "compiler/driver/scan_args.h"
#include "compiler/infer/wavelet/super_resolution.h"
#include "compiler/infer/wavelet/voxelize.h"
#include "formats/point_cloud_io.h"

namespace ramus::cli {

namespace {

struct EnhanceArgs {
  std::string scan, output, scanner;
  int grid = 64;
  std::uint64_t seed = 1;
  int classes = wavelet::kDefaultClasses;
};

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

void print_comparison(const wavelet::ResolutionComparison& c, std::size_t side) {
  auto precision = [](std::size_t hits, std::size_t voxels) {
    return voxels == 0 ? 0.0 : double(hits) / double(voxels);
  };
  std::printf("compared with the scan voxelized at %zu^3 (%zu voxels, %zu on the surface):\n", side,
              c.voxels_truth, c.surface_truth);
  std::printf("  enhanced:  IoU %.3f  precision %.3f  voxels %zu  surface %zu\n", c.iou_enhanced,
              precision(c.hits_enhanced, c.voxels_enhanced), c.voxels_enhanced, c.surface_enhanced);
  std::printf("  upsampled: IoU %.3f  precision %.3f  voxels %zu  surface %zu\n", c.iou_upsampled,
              precision(c.hits_upsampled, c.voxels_upsampled), c.voxels_upsampled,
              c.surface_upsampled);
}

int run_enhance(const EnhanceArgs& a, const GlobalOptions& global) {
  using namespace wavelet;
  if (!ends_with(a.output, ".ply") && !ends_with(a.output, ".xyz")) {
    throw UserError("-o: the output must end in .ply or .xyz, not '" + a.output + "'");
  }
  VoxelizeOptions vo;
  SuperResolutionOptions so;
  try {
    vo.levels = levels_for_side(std::uint64_t(a.grid < 0 ? 0 : a.grid));
    if (vo.levels < 2 || vo.levels >= kMaxLevels) throw std::invalid_argument("");
    (void)make_quantizer(1.0, a.classes);
  } catch (const std::invalid_argument& e) {
    throw UserError("--grid must be a power of two from 4 to 256 and --classes odd in [3, 255]");
  }
  so.seed = a.seed;
  so.classes = a.classes;
  const AlignedScan scan = read_aligned_scan(a.scan, a.scanner, "enhance", global.quiet);
  const AlignedCloud& aligned = scan.aligned;
  VoxelGrid grid = voxelize(aligned, vo);
  SuperResolution sr = super_resolve(grid, so);
  PointCloud out = voxel_centres(sr.grid, 0.5, &aligned.alignment);
  out.source = a.scan;
  if (ends_with(a.output, ".ply")) {
    write_point_cloud_ply(a.output, out);
  } else {
    write_point_cloud_xyz(a.output, out);
  }
  std::printf(
      "%s: %zu points -> %zu^3 grid (%zu voxels) -> %zu^3 enhanced (%zu voxels, %zu rules)\n",
      file_name(a.scan).c_str(), scan.cloud.size(), grid.n, grid.count_above(0), sr.grid.n,
      out.size(), sr.grammar.rules.size());
  VoxelizeOptions fine = vo;
  fine.levels = vo.levels + 1;
  print_comparison(compare_resolutions(grid, sr.grid, voxelize(aligned, fine)), sr.grid.n);
  return 0;
}

}  // namespace

void add_enhance(CLI::App& app, const GlobalOptions& global, std::function<int()>& run) {
  auto args = std::make_shared<EnhanceArgs>();
  CLI::App* sub = app.add_subcommand(
      "enhance", "super-resolution of a scan with its own voxel grammar (writes voxel centres)");
  sub->add_option("SCAN", args->scan, "point cloud (.ply .xyz .txt .asc .las .pcd)")->required();
  sub->add_option("-o,--output", args->output, "output points, .ply or .xyz")->required();
  sub->add_option("--grid", args->grid,
                  "voxel grid side of the input, a power of two (default 64)");
  sub->add_option("--seed", args->seed, "seed of the stochastic rule choice (default 1)");
  sub->add_option("--classes", args->classes, "coefficient classes, odd (default 17)");
  sub->add_option("--scanner", args->scanner, "scanner position x,y,z (default: from the file)");
  sub->callback(
      [args, &global, &run] { run = [args, &global] { return run_enhance(*args, global); }; });
}

}  // namespace ramus::cli
