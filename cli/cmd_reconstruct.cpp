// ramus reconstruct SCAN -o OUT.glb|.gltf|.obj|.ply|.json [--trees one|all] [--voxel V]
//                      [--no-leaves] [--seed S] [--method bsg|flood] [--merge ALPHA,BETA]
//                      [--up y|z] [--thin S] [--bases livny|stems]
//                      [--keep-stray | --stray-cluster N]
// ramus reconstruct DIR/manifest.json --tile K -o DIR/K.json ...
// Reads a laser scan, reconstructs the skeletons of the trees in it (Livny et al. 2010; see
// docs/reconstruction.md) and writes them as a mesh or as skeleton JSON. With a tile manifest
// (`ramus tile`), reconstructs tile K and keeps the trees whose base lies in its core
// (docs/scale.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "cli/command.h"
#include "cli/mesh_output.h"
#include "cli/output_path.h"
#include "cli/reconstruct_choice.h"
#include "cli/skeleton_output.h"
#include "core/skeleton_trees.h"
#include "formats/point_cloud_io.h"
#include "formats/tile_manifest.h"
#include "reconstruct/forest/core_trees.h"
#include "reconstruct/forest/stem_bases.h"
#include "reconstruct/merge/branch_merge.h"
#include "reconstruct/merge/merge_angles.h"
#include "reconstruct/reconstruct.h"

namespace ramus::cli {
namespace {

struct ReconstructArgs {
  std::string scan, output, trees = "all";
  ReconstructChoice method;  // --method, --voxel
  std::string merge_angles;  // "alpha,beta" of branch merging; empty: no merging
  bool no_leaves = false;
  bool keep_stray = false;  // --keep-stray: points alone in the air are reconstructed too
  int stray_cluster = -1;   // --stray-cluster N: smaller clusters are stray; -1: the default
  std::uint64_t seed = 1;
  std::string leaves_in_scan = "keep";  // foliage in the scan: keep, remove or auto
  std::string up;                       // --up of an OBJ or PLY mesh; empty: the default
  int tile = -1;                        // --tile K of a manifest
  double thin = 0;                      // --thin: voxel edge of thinning on read
  std::string bases = "livny";          // tree bases: Livny et al.'s density or stems
  bool given_trees = false;
};

// The points to reconstruct: a scan file, or tile K of a manifest (with its boxes).
struct ScanInput {
  PointCloud cloud;
  std::optional<TileEntry> tile;
  std::size_t read_points = 0;  // before thinning
};

ScanInput read_input(const ReconstructArgs& a) {
  ScanInput in;
  std::string path = a.scan;
  try {
    if (std::filesystem::path(a.scan).extension() == ".json") {
      if (a.tile < 0) throw UserError(a.scan + ": a tile manifest needs --tile K");
      const TileManifest m = read_tile_manifest(a.scan);
      if (std::size_t(a.tile) >= m.tiles.size()) {
        throw UserError(a.scan + ": there is no tile " + std::to_string(a.tile) +
                        " (the manifest has " + std::to_string(m.tiles.size()) +
                        ", numbered from 0)");
      }
      in.tile = m.tiles[std::size_t(a.tile)];
      path = (std::filesystem::path(a.scan).parent_path() / in.tile->file).string();
    } else if (a.tile >= 0) {
      throw UserError("--tile applies to a tile manifest (DIR/manifest.json from `ramus tile`)");
    }
    // Thinned while it is read: memory holds the thinned cloud, not the file's (docs/scale.md).
    ReadOptions options;
    options.thin = a.thin;
    ReadReport report;
    in.cloud = read_point_cloud(path, options, &report);
    in.read_points = report.points_before_thinning;
  } catch (const FormatError& e) {
    throw UserError(e.what());
  }
  return in;
}

// The ground-plane bounds of the cloud's points.
forest::GroundBox data_bounds(const PointCloud& c) {
  forest::GroundBox b{1e300, 1e300, -1e300, -1e300};
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Vec3 w = c.world(i);
    b.x0 = std::min(b.x0, w.x), b.y0 = std::min(b.y0, w.y);
    b.x1 = std::max(b.x1, w.x), b.y1 = std::max(b.y1, w.y);
  }
  return b;
}

forest::GroundBox ground_box(const TileBox& b) { return {b.x0, b.y0, b.x1, b.y1}; }

// Stem bases (reconstruct/forest/stem_bases.h): the ground goes, the bases are given.
ReconstructResult reconstruct_from_stems(const PointCloud& cloud, const ReconstructArgs& a,
                                         ReconstructOptions o) {
  const forest::StemBases stems = forest::find_stem_bases(cloud);
  if (stems.bases.empty()) {
    ReconstructResult r;
    r.notes.push_back("no stem in the slice 0.2-0.6 m above the ground: no tree base found");
    return r;
  }
  o.roots = stems.bases;
  ReconstructResult r =
      run_reconstruction(forest::without_ground(cloud, stems.ground), a.method, o);
  // The graph's root is the trunk's lowest surface point; the tree stands at the stem's centre on
  // the ground model, which is also where a tile's core test looks.
  for (Skeleton& t : r.trees) {
    const std::vector<std::uint32_t> roots = t.roots();
    if (roots.empty()) continue;
    Vec3& root = t.nodes[roots.front()].position;
    const Vec3* best = nullptr;
    for (const Vec3& b : stems.bases) {
      if (!best ||
          std::hypot(b.x - root.x, b.y - root.y) < std::hypot(best->x - root.x, best->y - root.y))
        best = &b;
    }
    if (best && std::hypot(best->x - root.x, best->y - root.y) < 1.0) root = *best;
  }
  return r;
}

int run_reconstruct(const ReconstructArgs& a, const GlobalOptions& global) {
  const mesh::UpAxis up = mesh_up_axis(a.up, a.output);  // a misplaced --up fails before the work
  if (a.bases == "stems" && a.method.method != "bsg") {
    throw UserError("--bases stems applies to --method bsg only");
  }
  ScanInput in = read_input(a);
  if (in.tile && a.given_trees)
    throw UserError("--trees does not apply to a tile: it keeps the trees of its core");
  const PointCloud& cloud = in.cloud;
  if (a.thin > 0 && !global.quiet) {
    std::fprintf(stderr, "ramus: thinned %zu points to %zu on a %g voxel grid\n", in.read_points,
                 cloud.size(), a.thin);
  }
  ReconstructOptions o;
  o.leaves = !a.no_leaves;
  o.remove_stray = !a.keep_stray;
  if (a.stray_cluster >= 0) {
    if (a.keep_stray) throw UserError("--stray-cluster does not apply with --keep-stray");
    o.stray_cluster = std::size_t(a.stray_cluster);
  }
  o.leaves_in_scan = a.leaves_in_scan == "keep"     ? LeafHandling::kKeep
                     : a.leaves_in_scan == "remove" ? LeafHandling::kRemove
                                                    : LeafHandling::kAuto;
  o.seed = a.seed;
  ReconstructResult r;
  try {
    r = a.bases == "stems" ? reconstruct_from_stems(cloud, a, o)
                           : run_reconstruction(cloud, a.method, o);
  } catch (const ReconstructError& e) {
    throw UserError(a.scan + ": " + e.what());
  }
  // The last note says why no tree was found, when none was: it becomes the error below.
  for (std::size_t i = 0; i < r.notes.size(); ++i) {
    if (r.trees.empty() && !in.tile && i + 1 == r.notes.size()) break;
    std::fprintf(stderr, "ramus: note: %s\n", r.notes[i].c_str());
  }
  if (in.tile) {
    // A tile keeps the trees whose base lies in its core, none too (an empty skeleton).
    const forest::CoreTrees kept =
        forest::keep_core_trees(r.trees, ground_box(in.tile->core), ground_box(in.tile->buffered),
                                data_bounds(cloud), 2 * std::max(r.voxel_size, 0.01));
    for (std::size_t k : kept.touching) {
      const Vec3 b = kept.kept[k].nodes[kept.kept[k].roots().front()].position;
      std::fprintf(stderr,
                   "ramus: warning: tile %d: the tree at (%.2f, %.2f) reaches the buffer's edge, "
                   "so its crown may be cut: the buffer must cover half a crown's width (give "
                   "`ramus tile` a larger --buffer)\n",
                   in.tile->id, b.x, b.y);
    }
    write_skeleton_output(join_trees(kept.kept), a.output,
                          std::filesystem::path(a.scan).stem().string(), up);
    if (!global.quiet) {
      std::fprintf(
          stderr,
          "ramus: wrote %s (tile %d: %zu of %zu tree(s) based in its core) from %zu points "
          "in %.2f s\n",
          a.output.c_str(), in.tile->id, kept.kept.size(), r.trees.size(), cloud.size(),
          r.timings.total);
    }
    return 0;
  }
  if (r.trees.empty()) {
    throw UserError(a.scan + ": " + (r.notes.empty() ? "no tree found" : r.notes.back()));
  }
  std::vector<Skeleton> chosen = r.trees;
  if (a.trees == "one") {
    // The tree with the most wood.
    auto best = std::max_element(r.trees.begin(), r.trees.end(), [](const auto& x, const auto& y) {
      return x.total_length() < y.total_length();
    });
    chosen = {*best};
  }
  Skeleton forest = join_trees(chosen);
  if (!a.merge_angles.empty()) {
    const merge::MergeStats ms =
        merge::merge_branches(forest, merge::parse_merge_angles(a.merge_angles));
    if (!global.quiet) {
      std::fprintf(stderr,
                   "ramus: merged branches: %zu -> %zu nodes (%zu vertical, %zu horizontal)\n",
                   ms.nodes_before, ms.nodes_after, ms.vertical_merges, ms.horizontal_merges);
    }
  }
  write_skeleton_output(forest, a.output, std::filesystem::path(a.scan).stem().string(), up);
  if (!global.quiet) {
    std::fprintf(stderr,
                 "ramus: wrote %s (%zu of %zu tree(s), %zu nodes, %zu leaves) from %zu points "
                 "in %.2f s\n",
                 a.output.c_str(), chosen.size(), r.trees.size(), forest.size(),
                 forest.organs.size(), cloud.size(), r.timings.total);
  }
  return 0;
}

}  // namespace

void add_reconstruct(CLI::App& app, const GlobalOptions& global, std::function<int()>& run) {
  auto args = std::make_shared<ReconstructArgs>();
  CLI::App* sub =
      app.add_subcommand("reconstruct", "scan -> tree skeletons -> mesh (Livny et al.)");
  sub->add_option("scan", args->scan,
                  "point cloud: .ply, .xyz/.txt/.asc/.csv, .las, .laz, .pcd; or a tile manifest "
                  "(DIR/manifest.json of `ramus tile`) with --tile")
      ->required();
  output_path(sub->add_option("-o,--output", args->output,
                              "output: .glb, .gltf, .obj, .ply (mesh) or .json"))
      ->required()
      ->check(CLI::Validator(check_skeleton_output, "FILE", "output file"));
  sub->add_option("--tile", args->tile,
                  "reconstruct tile K of the manifest and keep the trees whose base lies in its "
                  "core")
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--thin", args->thin,
                  "keep the first point of each voxel of this edge (metres) while the scan is read")
      ->check(CLI::PositiveNumber);
  sub->add_option("--bases", args->bases,
                  "tree bases: livny (density near the ground, default) or stems (stems at "
                  "breast height over a ground model: forest plots, docs/scale.md)")
      ->check(CLI::IsMember({"livny", "stems"}));
  sub->add_option("--trees", args->trees, "all trees in the scan, or only the largest one")
      ->check(CLI::IsMember({"one", "all"}));
  sub->add_flag("--no-leaves", args->no_leaves, "do not synthesize leaves at the branch tips");
  sub->add_flag("--keep-stray", args->keep_stray,
                "reconstruct stray points too: those with fewer than two others within four "
                "voxels (default: ignored as stray returns, e.g. mixed pixels at twig edges)");
  sub->add_option("--stray-cluster", args->stray_cluster,
                  "points in a cluster (linked by steps within four voxels) of fewer than N "
                  "points are stray too: runs of mixed points (5 for a phase-shift scanner; "
                  "default 1: no cluster is stray for its size)")
      ->check(CLI::Range(0, 1000));
  sub->add_option("--leaves-in-scan", args->leaves_in_scan,
                  "foliage in the scan: keep every point (default), remove it first (wood/leaf "
                  "separation), or auto: remove it only when the separation finds a foliage mode "
                  "holding at least 25% of the points in a scan fine enough to resolve leaves "
                  "(the note gives the evidence)")
      ->check(CLI::IsMember({"auto", "keep", "remove"}));
  sub->add_option("--seed", args->seed, "seed of the synthesized leaves");
  add_up_option(sub, args->up);
  add_reconstruct_choice_options(*sub, args->method, "--method", "");
  sub->add_option("--merge", args->merge_angles,
                  "merge branches: ALPHA,BETA degrees (collinear chains below ALPHA, sibling "
                  "leaf branches below BETA), e.g. 10,15")
      ->check(CLI::Validator(
          [](const std::string& t) -> std::string {
            try {
              merge::parse_merge_angles(t);
              return "";
            } catch (const std::invalid_argument& e) {
              return e.what();
            }
          },
          "ALPHA,BETA", "merge angles"));
  sub->callback([args, sub, &global, &run] {
    args->given_trees = sub->count("--trees") > 0;
    run = [args, &global] { return run_reconstruct(*args, global); };
  });
}

}  // namespace ramus::cli
