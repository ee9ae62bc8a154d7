// ramus enhance SCAN -o OUT.ply|.xyz [--grid 64] [--seed 1] [--classes 17] [--scanner x,y,z]
// ramus enhance SCAN --levels K -o OUT.glb|.gltf|.obj|.ply|.xyz [--grid 64] [--seed 1] ...
// Without --levels: super-resolution of a scan with its own voxel grammar (Friedman & Stamos 2013,
// III-C/III-D): the scan is aligned and voxelized at --grid, a voxel grammar is learned from its
// nonstandard Haar pyramid, the grammar synthesizes the wavelets of one more level, and the
// inverse transform gives a grid of twice the side. Writes the centres of the occupied voxels
// (world coordinates) and prints how the result and plain upsampling compare with the scan
// voxelized at twice the side.
// With --levels K: enhancement by the L-rules (IV-B): the grammar `ramus infer --method wavelet`
// would write is derived K steps beyond the finest dyad it regenerates, each step refining every
// vector into the vectors of the next finer dyad. Writes the tree as a mesh (.glb .gltf .obj) or
// as points along its branches (.ply .xyz), in world coordinates.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "backends/mesh/gltf_writer.h"
#include "backends/mesh/openmesh_writer.h"
#include "mesh/tree_mesh.h"
#include "cli/command.h"
#include "cli/mesh_output.h"
#include "cli/output_path.h"
#include "cli/scan_args.h"
#include "compiler/derive.h"
#include "compiler/pipeline.h"
#include "compiler/turtle.h"
#include "formats/point_cloud_io.h"
#include "infer/wavelet/fidelity.h"
#include "infer/wavelet/infer_grammar.h"
#include "infer/wavelet/super_resolution.h"
#include "infer/wavelet/voxelize.h"

namespace ramus::cli {

namespace {

struct EnhanceArgs {
  std::string scan, output, scanner;
  int grid = 64;
  std::uint64_t seed = 1;
  int classes = wavelet::kDefaultClasses;
  int levels = 0;  // > 0: L-rule enhancement by this many derivation steps
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

// The skeleton in world coordinates: positions and turtle frames rotated back (III-A).
Skeleton to_world(Skeleton s, const wavelet::Alignment& al) {
  auto direction = [&al](const Vec3& v) { return al.to_world(v) - al.to_world(Vec3{}); };
  for (SkeletonNode& n : s.nodes) {
    n.position = al.to_world(n.position);
    n.heading = direction(n.heading), n.left = direction(n.left), n.up = direction(n.up);
  }
  for (OrganAnchor& o : s.organs) {
    o.position = al.to_world(o.position);
    o.heading = direction(o.heading), o.left = direction(o.left), o.up = direction(o.up);
  }
  return s;
}

// Section IV-B: "L-System productions can be applied iteratively each time yielding a more
// intricately detailed structure." The inferred grammar derives `derive` steps to regenerate the
// finest dyad; K more steps go K dyads beyond the scan's resolution.
int run_enhance_levels(const EnhanceArgs& a, const GlobalOptions& global) {
  using namespace wavelet;
  const bool mesh_out =
      ends_with(a.output, ".glb") || ends_with(a.output, ".gltf") || ends_with(a.output, ".obj");
  if (!mesh_out && !ends_with(a.output, ".ply") && !ends_with(a.output, ".xyz")) {
    throw UserError(
        "-o: with --levels the output must end in .glb, .gltf, .obj, .ply or .xyz, not '" +
        a.output + "'");
  }
  WaveletInferOptions io;
  io.grid = a.grid;
  io.seed = a.seed;
  io.classes = a.classes;
  io.source = file_name(a.scan);
  try {
    validate_options(io);
    (void)make_quantizer(1.0, a.classes);
  } catch (const std::invalid_argument& e) {
    throw UserError(std::string(e.what()) + " (--classes must be odd in [3, 255])");
  }
  const AlignedScan scan = read_aligned_scan(a.scan, a.scanner, "enhance", global.quiet);
  WaveletInference inference;
  try {
    inference = infer_wavelet_grammar(scan.aligned, io);
  } catch (const std::invalid_argument& e) {
    throw UserError(a.scan + ": " + e.what());
  }
  SourceManager sources;
  DiagnosticSink diagnostics;
  const ir::Grammar g =
      lower_text("inferred.ramus", inference.ramus_text, GrowOptions{}, sources, diagnostics);
  const int steps = g.settings.derive + a.levels;
  DeriveOptions d;
  d.steps = steps;
  DeriveStats stats;
  TurtleOptions t;
  t.seed = g.settings.seed;
  t.steps = steps;
  Skeleton tree;
  try {
    tree = interpret(g, derive(g, d, &stats), t);
  } catch (const DeriveError& e) {
    throw UserError(e.what());
  }
  // The scan at the input resolution, to compare with and to size the output sampling.
  VoxelizeOptions vo;
  vo.levels = levels_for_side(std::uint64_t(a.grid));
  const VoxelGrid input = voxelize(scan.aligned, vo);
  const Skeleton world = to_world(tree, scan.aligned.alignment);
  if (mesh_out) {
    mesh::MeshOptions mo;
    mo.name = std::filesystem::path(a.scan).stem().string();  // not the output name: same bytes
    try {
      if (ends_with(a.output, ".obj")) {
        // The OBJ default (y up, as Blender reads it); enhance has no --up of its own.
        mesh::write_openmesh(mesh::build_tree_mesh(world, mo, 0), a.output,
                             mesh_up_axis("", a.output));
      } else {
        mesh::write_gltf(mesh::build_tree_lods(world, mo), a.output);
      }
    } catch (const mesh::MeshError& e) {
      throw UserError(a.output + ": " + e.what());
    }
  } else {
    PointCloud out;
    out.source = a.scan;
    out.offset = scan.aligned.alignment.root;
    // Points half a finest cell apart: a cell of dyad L-1+K is 2^(1-K) input voxels.
    const double step = input.voxel_size / double(1 << a.levels);
    for (const Vec3& p : sample_skeleton(world, step))
      out.positions.push_back(Vec3f(p - out.offset));
    if (ends_with(a.output, ".ply")) {
      write_point_cloud_ply(a.output, out);
    } else {
      write_point_cloud_xyz(a.output, out);
    }
  }
  std::printf("%s: %zu points -> %zu^3 grid -> grammar with %zu productions, axiom dyad %d\n",
              file_name(a.scan).c_str(), scan.cloud.size(), inference.grid_side,
              inference.productions, inference.axiom_level);
  std::printf("derived %d step(s) (%d beyond the scan's finest dyad): modules per step", steps,
              a.levels);
  for (std::size_t n : stats.lengths) std::printf(" %zu", n);
  std::printf("\nenhanced tree: %zu nodes; voxel IoU with the scan at %zu^3: %.3f\n", tree.size(),
              input.n, voxel_iou(input, 0, voxelize_skeleton(tree, input), 0));
  return 0;
}

int run_enhance(const EnhanceArgs& a, const GlobalOptions& global) {
  using namespace wavelet;
  if (a.levels > 0) return run_enhance_levels(a, global);
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
      "enhance",
      "super-resolution of a scan with its own voxel grammar, or (--levels) its L-rules iterated");
  sub->add_option("SCAN", args->scan, "point cloud (.ply .xyz .txt .asc .las .laz .pcd)")
      ->required();
  output_path(sub->add_option("-o,--output", args->output, "output points, .ply or .xyz"))
      ->required();
  sub->add_option("--grid", args->grid,
                  "voxel grid side of the input, a power of two (default 64)");
  sub->add_option("--seed", args->seed, "seed of the stochastic rule choice (default 1)");
  sub->add_option("--classes", args->classes, "coefficient classes, odd (default 17)");
  sub->add_option("--scanner", args->scanner, "scanner position x,y,z (default: from the file)");
  sub->add_option("--levels", args->levels,
                  "enhance by the inferred L-rules instead: derive K steps beyond the scan's "
                  "finest dyad (output .glb .gltf .obj mesh, or .ply .xyz points)")
      ->check(CLI::Range(1, 6));
  sub->callback(
      [args, &global, &run] { run = [args, &global] { return run_enhance(*args, global); }; });
}

}  // namespace ramus::cli
