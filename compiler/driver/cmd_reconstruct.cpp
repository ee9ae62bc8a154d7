// ramus reconstruct SCAN -o OUT.glb|.gltf|.obj|.ply|.json [--trees one|all] [--voxel V]
//                      [--no-leaves] [--seed S] [--method bsg|flood] [--merge ALPHA,BETA]
// Reads a laser scan, reconstructs the skeletons of the trees in it (Livny et al. 2010; see
// docs/reconstruction.md) and writes them as a mesh or as skeleton JSON.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "backends/mesh/gltf_writer.h"
#include "backends/mesh/openmesh_writer.h"
#include "backends/mesh/tree_mesh.h"
#include "compiler/driver/command.h"
#include "compiler/infer/flood/flood_skeleton.h"
#include "compiler/infer/merge/branch_merge.h"
#include "compiler/infer/merge/merge_angles.h"
#include "compiler/infer/reconstruct.h"
#include "formats/point_cloud_io.h"
#include "formats/skeleton_json.h"

namespace ramus::cli {
namespace {

struct ReconstructArgs {
  std::string scan, output, trees = "all";
  std::string method = "bsg";  // bsg (Livny et al.) or flood (voxel flood fill)
  std::string merge_angles;    // "alpha,beta" of branch merging; empty: no merging
  double voxel = 0;
  bool fine = false;  // the fine preset of docs/reconstruction.md (Accuracy)
  bool no_leaves = false;
  std::uint64_t seed = 1;
};

// All trees as one forest (a Skeleton may have several roots).
Skeleton merge(const std::vector<Skeleton>& trees) {
  Skeleton out;
  for (const Skeleton& t : trees) {
    const auto base = std::uint32_t(out.nodes.size());
    for (SkeletonNode n : t.nodes) {
      if (n.parent != kNoParent) n.parent += base;
      out.nodes.push_back(n);
    }
    for (OrganAnchor a : t.organs) {
      a.node += base;
      out.organs.push_back(a);
    }
  }
  return out;
}

void write_output(const Skeleton& s, const std::string& path, const std::string& name) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".json") return write_skeleton_json(path, s);
  mesh::MeshOptions mo;
  mo.name = name;
  try {
    if (ext == ".glb" || ext == ".gltf") {
      mesh::write_gltf({mesh::build_tree_mesh(s, mo)}, path);
    } else {
      mesh::write_openmesh(mesh::build_tree_mesh(s, mo), path);
    }
  } catch (const mesh::MeshError& e) {
    throw UserError(e.what());
  }
}

int run_reconstruct(const ReconstructArgs& a, const GlobalOptions& global) {
  PointCloud cloud;
  try {
    cloud = read_point_cloud(a.scan);
  } catch (const FormatError& e) {
    throw UserError(e.what());
  }
  ReconstructOptions o;
  o.voxel_size = a.voxel;
  if (a.fine) {
    // One point spacing per voxel resolves twigs of 1-1.3 cm; fewer contraction steps and rounds
    // keep curved whips in place (docs/reconstruction.md, Accuracy).
    o.voxel_spacings = 1;
    o.voxel_height_floor = 1.0 / 1000;
    o.contraction_steps = 10;
    o.max_iterations = 2;
  }
  o.leaves = !a.no_leaves;
  o.seed = a.seed;
  ReconstructResult r;
  try {
    if (a.method == "flood") {
      flood::FloodOptions fo;
      fo.voxel_size = a.voxel;
      r = flood::flood_reconstruct(cloud, fo);
    } else {
      r = reconstruct(cloud, o);
    }
  } catch (const ReconstructError& e) {
    throw UserError(a.scan + ": " + e.what());
  }
  for (std::size_t i = 0; i + 1 < r.notes.size(); ++i) {
    std::fprintf(stderr, "ramus: note: %s\n", r.notes[i].c_str());
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
  Skeleton forest = merge(chosen);
  if (!a.merge_angles.empty()) {
    const merge::MergeStats ms =
        merge::merge_branches(forest, merge::parse_merge_angles(a.merge_angles));
    if (!global.quiet) {
      std::fprintf(stderr,
                   "ramus: merged branches: %zu -> %zu nodes (%zu vertical, %zu horizontal)\n",
                   ms.nodes_before, ms.nodes_after, ms.vertical_merges, ms.horizontal_merges);
    }
  }
  write_output(forest, a.output, std::filesystem::path(a.scan).stem().string());
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
  sub->add_option("scan", args->scan, "point cloud: .ply, .xyz/.txt/.asc/.csv, .las, .pcd")
      ->required();
  sub->add_option("-o,--output", args->output, "output: .glb, .gltf, .obj, .ply (mesh) or .json")
      ->required()
      ->check(CLI::Validator(
          [](const std::string& p) -> std::string {
            const std::string e = std::filesystem::path(p).extension().string();
            return e == ".glb" || e == ".gltf" || e == ".obj" || e == ".ply" || e == ".json"
                       ? ""
                       : "the output must end in .glb, .gltf, .obj, .ply or .json";
          },
          "FILE", "output file"));
  sub->add_option("--trees", args->trees, "all trees in the scan, or only the largest one")
      ->check(CLI::IsMember({"one", "all"}));
  sub->add_option("--voxel", args->voxel, "voxel size of the graph (default: from the data)")
      ->check(CLI::NonNegativeNumber);
  sub->add_flag(
      "--fine", args->fine,
      "bsg: one point spacing per voxel, 10 contraction steps, 2 rounds (more accurate on "
      "thin branches of dense scans, about twice as slow; thick branches may keep "
      "parallel paths)");
  sub->add_flag("--no-leaves", args->no_leaves, "do not synthesize leaves at the branch tips");
  sub->add_option("--seed", args->seed, "seed of the synthesized leaves");
  sub->add_option("--method", args->method,
                  "bsg: branch-structure graph (Livny et al.); flood: voxel flood fill (faster, "
                  "no leaves)")
      ->check(CLI::IsMember({"bsg", "flood"}));
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
  sub->callback(
      [args, &global, &run] { run = [args, &global] { return run_reconstruct(*args, global); }; });
}

}  // namespace ramus::cli
