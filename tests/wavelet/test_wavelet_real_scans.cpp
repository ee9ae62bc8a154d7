// The wavelet stages on the real scans of ../shared/data (see its SOURCES.md): compression
// figures in the range of the paper's Table I, super-resolution against a finer voxelization of
// the same cloud, and valid per-dyad skeletons. Skipped with a message when the data is absent.
#include <catch2/catch.hpp>
#include <filesystem>

#include "formats/point_cloud_io.h"
#include "infer/wavelet/compression.h"
#include "infer/wavelet/dyad_tree.h"
#include "infer/wavelet/super_resolution.h"
#include "infer/wavelet/voxelize.h"

using namespace ramus;
using namespace ramus::wavelet;

namespace {

std::string scan_path(const char* name) { return std::string(RAMUS_SHARED_DIR) + "/data/" + name; }

}  // namespace

TEST_CASE("real scans: compression figures and lossy reconstruction and dyad skeletons",
          "[wavelet]") {
  for (const char* name : {"adtree_tree1.xyz", "pytlidar_tree_1.las", "rtwig_cloud.txt"}) {
    std::string path = scan_path(name);
    if (!std::filesystem::exists(path)) {
      WARN("skipped: " << path << " is missing");
      continue;
    }
    INFO(name);
    PointCloud cloud = read_point_cloud(path);
    AlignedCloud aligned = align_cloud(cloud);
    CHECK(aligned.alignment.source == ScannerSource::centroid);  // these files carry no scanner
    VoxelizeOptions vo;
    vo.levels = 6;
    VoxelGrid grid = voxelize(aligned, vo);
    WaveletPyramid p = haar_forward(grid, Decomposition::standard);
    CompressionStats s = compression_stats(grid, p);
    // Table I reports 64-81 % lossless and 92-96 % lossy for denser scans; sparse scans of bare
    // branches have more zero coefficients. Lossy reconstruction keeps almost every voxel.
    CHECK(s.lossless_ratio > 0.6);
    CHECK(s.lossless_ratio < 0.99);
    CHECK(s.lossy_ratio > 0.9);
    CHECK(s.lossy_ratio > s.lossless_ratio);
    CHECK(s.lossy_iou > 0.95);
    CHECK(s.lossy_iou < 1.0);

    for (const DyadTree& t : dyad_trees(p)) {
      Skeleton sk = to_skeleton(t, p, {}, &aligned.alignment);
      CHECK(sk.validate().empty());
      CHECK(sk.size() == t.size());
    }
    DyadTree finest = dyad_tree(p, 5);
    CHECK(finest.size() > 100);
    // Rooted at the lowest significant node, near the bottom of the dyad (its z starts at 32).
    for (const auto& cell : finest.cells) CHECK(cell[2] >= finest.cells[finest.root][2]);
    CHECK(finest.cells[finest.root][2] < 32 + 4);
  }
}

TEST_CASE("real scans: super-resolution against a finer voxelization", "[wavelet]") {
  std::string path = scan_path("adtree_tree1.xyz");
  if (!std::filesystem::exists(path)) {
    WARN("skipped: " << path << " is missing");
    return;
  }
  AlignedCloud aligned = align_cloud(read_point_cloud(path));
  VoxelizeOptions vo;
  vo.levels = 5;
  VoxelGrid coarse = voxelize(aligned, vo);
  vo.levels = 6;
  VoxelGrid truth = voxelize(aligned, vo);  // the same cube, twice the resolution
  SuperResolution sr = super_resolve(coarse);
  ResolutionComparison c = compare_resolutions(coarse, sr.grid, truth);
  // The synthetic details thin the upsampled voxels towards the finer truth: fewer voxels, a
  // higher share of them confirmed by the truth; the IoU stays close to plain upsampling's.
  CHECK(c.voxels_enhanced < c.voxels_upsampled);
  CHECK(c.voxels_enhanced > c.voxels_truth / 2);
  CHECK(double(c.hits_enhanced) / double(c.voxels_enhanced) >
        double(c.hits_upsampled) / double(c.voxels_upsampled));
  CHECK(c.iou_enhanced > 0.8 * c.iou_upsampled);
  SuperResolution again = super_resolve(coarse);
  CHECK(again.grid.values == sr.grid.values);
}
