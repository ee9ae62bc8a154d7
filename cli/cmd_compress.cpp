// ramus compress SCAN [--grid 64] [--gamma 0.2] [--values occupancy|density]
//                     [--decomposition standard|nonstandard] [--scale orthonormal|averaging]
//                     [--scanner x,y,z] [--no-header]
// One row of Table I of Friedman & Stamos 2013 (IV-A) for a scan: the share of Haar wavelet
// coefficients equal to zero (lossless), the share below gamma (lossy) and the voxel IoU of the
// lossy reconstruction, as a Markdown table row (with its header unless --no-header).
#include <cstdio>
#include <memory>
#include <string>

#include "cli/command.h"
#include "cli/scan_args.h"
#include "infer/wavelet/compression.h"
#include "infer/wavelet/haar.h"
#include "infer/wavelet/voxelize.h"

namespace ramus::cli {

namespace {

struct CompressArgs {
  std::string scan;
  int grid = 64;
  double gamma = 0.2;
  std::string values = "occupancy";
  std::string decomposition = "standard";
  std::string scale = "orthonormal";
  std::string scanner;
  bool no_header = false;
};

int run_compress(const CompressArgs& a, const GlobalOptions& global) {
  using namespace wavelet;
  VoxelizeOptions vo;
  Decomposition decomposition;
  CoefficientScale scale;
  try {
    vo.levels = levels_for_side(std::uint64_t(a.grid < 0 ? 0 : a.grid));
    vo.values = parse_voxel_values(a.values);
    decomposition =
        a.decomposition == "standard" ? Decomposition::standard : Decomposition::nonstandard;
    scale = a.scale == "orthonormal" ? CoefficientScale::orthonormal : CoefficientScale::averaging;
  } catch (const std::invalid_argument& e) {
    throw UserError(std::string("--grid: ") + e.what());
  }
  const AlignedScan scan = read_aligned_scan(a.scan, a.scanner, "compress", global.quiet);
  VoxelGrid grid = voxelize(scan.aligned, vo);
  WaveletPyramid pyramid = haar_forward(grid, decomposition);
  CompressionStats s = compression_stats(grid, pyramid, a.gamma, scale);
  if (!a.no_header) {
    std::printf(
        "| file | points | grid | voxels | lossless %% | lossy %% (gamma %g) | lossy IoU |\n",
        a.gamma);
    std::printf("|---|---:|---:|---:|---:|---:|---:|\n");
  }
  std::printf("| %s | %zu | %d^3 | %zu | %.1f | %.1f | %.3f |\n", file_name(a.scan).c_str(),
              scan.cloud.size(), a.grid, s.input_voxels, 100 * s.lossless_ratio,
              100 * s.lossy_ratio, s.lossy_iou);
  return 0;
}

}  // namespace

void add_compress(CLI::App& app, const GlobalOptions& global, std::function<int()>& run) {
  auto args = std::make_shared<CompressArgs>();
  CLI::App* sub = app.add_subcommand(
      "compress", "wavelet compression figures of a scan (Friedman & Stamos 2013, Table I)");
  sub->add_option("SCAN", args->scan, "point cloud (.ply .xyz .txt .asc .las .laz .pcd)")
      ->required();
  sub->add_option("--grid", args->grid, "voxel grid side, a power of two (default 64)");
  sub->add_option("--gamma", args->gamma, "lossy threshold on |coefficient| (default 0.2)")
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--values", args->values, "voxel values (default occupancy)")
      ->check(CLI::IsMember({"occupancy", "density"}));
  sub->add_option("--decomposition", args->decomposition, "Haar decomposition (default standard)")
      ->check(CLI::IsMember({"standard", "nonstandard"}));
  sub->add_option("--scale", args->scale,
                  "coefficients gamma is compared with (default orthonormal)")
      ->check(CLI::IsMember({"orthonormal", "averaging"}));
  sub->add_option("--scanner", args->scanner, "scanner position x,y,z (default: from the file)");
  sub->add_flag("--no-header", args->no_header, "print the row only");
  sub->callback(
      [args, &global, &run] { run = [args, &global] { return run_compress(*args, global); }; });
}

}  // namespace ramus::cli
