// ramus reconstruct SCAN -o OUT.glb|.gltf|.obj|.ply|.json [--trees one|all] [--voxel V]
//                      [--no-leaves] [--seed S] [--method bsg|flood] [--merge ALPHA,BETA]
//                      [--up y|z]
// Reads a laser scan, reconstructs the skeletons of the trees in it (Livny et al. 2010; see
// docs/reconstruction.md) and writes them as a mesh or as skeleton JSON.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "backends/mesh/gltf_writer.h"
#include "backends/mesh/openmesh_writer.h"
#include "backends/mesh/tree_mesh.h"
#include "cli/command.h"
#include "cli/mesh_output.h"
#include "cli/output_path.h"
#include "cli/reconstruct_choice.h"
#include "formats/point_cloud_io.h"
#include "formats/skeleton_json.h"
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
  std::uint64_t seed = 1;
  std::string leaves_in_scan = "keep";  // foliage in the scan: keep, remove or auto
  std::string up;                       // --up of an OBJ or PLY mesh; empty: the default
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

// A scan's skeleton is in its world (UTM) coordinates: the mesh is built about a local origin
// that the writers record (docs/mesh.md), and skeleton JSON keeps the doubles as they are.
void write_output(const Skeleton& s, const std::string& path, const std::string& name,
                  mesh::UpAxis up) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".json") return write_skeleton_json(path, s);
  mesh::MeshOptions mo;
  mo.name = name;
  try {
    if (ext == ".glb" || ext == ".gltf") {
      mesh::write_gltf({mesh::build_tree_mesh(s, mo)}, path);
    } else {
      mesh::write_openmesh(mesh::build_tree_mesh(s, mo), path, up);
    }
  } catch (const mesh::MeshError& e) {
    throw UserError(e.what());
  }
}

int run_reconstruct(const ReconstructArgs& a, const GlobalOptions& global) {
  const mesh::UpAxis up = mesh_up_axis(a.up, a.output);  // a misplaced --up fails before the work
  PointCloud cloud;
  try {
    cloud = read_point_cloud(a.scan);
  } catch (const FormatError& e) {
    throw UserError(e.what());
  }
  ReconstructOptions o;
  o.leaves = !a.no_leaves;
  o.leaves_in_scan = a.leaves_in_scan == "keep"     ? LeafHandling::kKeep
                     : a.leaves_in_scan == "remove" ? LeafHandling::kRemove
                                                    : LeafHandling::kAuto;
  o.seed = a.seed;
  ReconstructResult r;
  try {
    r = run_reconstruction(cloud, a.method, o);
  } catch (const ReconstructError& e) {
    throw UserError(a.scan + ": " + e.what());
  }
  // The last note says why no tree was found, when none was: it becomes the error below.
  for (std::size_t i = 0; i < r.notes.size(); ++i) {
    if (r.trees.empty() && i + 1 == r.notes.size()) break;
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
  write_output(forest, a.output, std::filesystem::path(a.scan).stem().string(), up);
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
  sub->add_option("scan", args->scan, "point cloud: .ply, .xyz/.txt/.asc/.csv, .las, .laz, .pcd")
      ->required();
  output_path(sub->add_option("-o,--output", args->output,
                              "output: .glb, .gltf, .obj, .ply (mesh) or .json"))
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
  sub->add_flag("--no-leaves", args->no_leaves, "do not synthesize leaves at the branch tips");
  sub->add_option("--leaves-in-scan", args->leaves_in_scan,
                  "foliage in the scan: keep every point (default), remove it first (wood/leaf "
                  "separation), or auto: remove it when at least 25% of the points look like "
                  "leaves")
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
  sub->callback(
      [args, &global, &run] { run = [args, &global] { return run_reconstruct(*args, global); }; });
}

}  // namespace ramus::cli
