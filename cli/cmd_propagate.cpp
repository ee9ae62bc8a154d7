// ramus propagate FILE -n K -o DIR [--seed S] [--jitter X] [--steps N] [--format
// glb|gltf|obj|ply|rmb] [--up y|z]
//                  [-D name=value]... [--system NAME] [--max-modules N]
// Geometry propagation (Friedman & Stamos 2013, IV-C): K similar but distinct trees from one
// grammar, tree k grown with its own seed and a perturbed axiom (infer/wavelet/
// propagate.h). Writes DIR/tree_000.glb ... (meshes through the same pipeline as `ramus build`),
// or with --format rmb the K perturbed grammars themselves in the binary format.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "backends/mesh/gltf_writer.h"
#include "backends/mesh/openmesh_writer.h"
#include "mesh/tree_mesh.h"
#include "cli/grow_args.h"
#include "cli/mesh_output.h"
#include "cli/output_path.h"
#include "compiler/derive.h"
#include "compiler/turtle.h"
#include "core/atomic_file.h"
#include "core/rng.h"
#include "formats/rmb/rmb.h"
#include "grammar/loader.h"
#include "infer/wavelet/propagate.h"

namespace ramus::cli {
namespace {

struct PropagateArgs {
  GrowArgs grow;  // file, -D, --system, --max-modules (its seed and steps are set from below)
  int count = 0;
  std::string dir;
  std::optional<std::uint64_t> seed;
  std::optional<int> steps;
  double jitter = 0.1;
  std::string format = "glb";
  std::string up;  // --up of OBJ and PLY meshes; empty: the format's default
};

// Order-sensitive hash of a skeleton's geometry: equal trees hash equal, so two outputs that
// hash differently are distinct.
std::uint64_t skeleton_hash(const Skeleton& s) {
  std::uint64_t h = mix64(s.nodes.size());
  auto add = [&h](double v) {
    std::uint64_t bits;
    static_assert(sizeof bits == sizeof v);
    std::memcpy(&bits, &v, sizeof v);
    h = mix64(h ^ bits);
  };
  for (const SkeletonNode& n : s.nodes) {
    add(n.position.x), add(n.position.y), add(n.position.z), add(n.radius), add(double(n.parent));
  }
  return h;
}

std::string tree_name(int k, int count) {
  std::string digits = std::to_string(k);
  const std::size_t width = std::max<std::size_t>(3, std::to_string(count - 1).size());
  return "tree_" + std::string(width - std::min(width, digits.size()), '0') + digits;
}

Skeleton grow(const ir::Grammar& g, const PropagateArgs& a) {
  DeriveOptions d;
  d.max_modules = a.grow.max_modules;
  d.max_bytes = a.grow.max_memory;
  TurtleOptions t;
  t.seed = g.settings.seed;
  t.steps = g.settings.derive;
  t.max_modules = a.grow.max_modules;
  t.max_bytes = a.grow.max_memory;
  try {
    return interpret(g, derive(g, d), t);
  } catch (const DeriveError& e) {
    throw UserError(e.what());
  }
}

std::size_t write_mesh(const Skeleton& skeleton, const std::string& path, const std::string& name,
                       bool gltf, mesh::UpAxis up) {
  mesh::MeshOptions o;
  o.name = name;
  mesh::MeshReport report;
  try {
    if (gltf) {
      const auto lods = mesh::build_tree_lods(skeleton, o, &report);
      mesh::write_gltf(lods, path);
      return lods.front().triangle_count();
    }
    const mesh::TreeMesh m = mesh::build_tree_mesh(skeleton, o, 0, &report);
    mesh::write_openmesh(m, path, up);
    return m.triangle_count();
  } catch (const mesh::MeshError& e) {
    throw UserError(path + ": " + e.what());
  }
}

int run_propagate(const PropagateArgs& a, const GlobalOptions& global) {
  const mesh::UpAxis up = mesh_up_axis(a.up, "tree." + a.format);  // --up with glb or rmb fails
  std::optional<ir::Grammar> lowered = lower_for_cli(a.grow);
  if (!lowered) return 1;
  ir::Grammar& g = *lowered;
  if (a.steps) g.settings.derive = *a.steps;
  wavelet::PropagateOptions po;
  po.seed = a.seed.value_or(g.settings.seed);
  po.jitter = a.jitter;
  std::error_code ec;
  std::filesystem::create_directories(a.dir, ec);
  if (ec) throw UserError("-o: cannot create the folder '" + a.dir + "': " + ec.message());
  const bool rmb = a.format == "rmb";
  if (rmb) make_locations_portable(g, a.grow.file, default_stdlib_dirs());

  std::vector<std::uint64_t> hashes;
  for (int k = 0; k < a.count; ++k) {
    wavelet::PropagatedGrammar p = wavelet::propagate_grammar(g, std::uint64_t(k), po);
    const Skeleton tree = grow(p.grammar, a);
    const std::uint64_t h = skeleton_hash(tree);
    for (std::size_t j = 0; j < hashes.size(); ++j) {
      if (hashes[j] != h) continue;
      throw UserError(tree_name(int(j), a.count) + " and " + tree_name(k, a.count) +
                      " are the same tree: the grammar is deterministic and its axiom has no "
                      "non-zero numeric argument to perturb (give the axiom modules arguments, "
                      "or a larger --jitter)");
    }
    hashes.push_back(h);
    const std::string name = tree_name(k, a.count);
    const std::string path = (std::filesystem::path(a.dir) / (name + "." + a.format)).string();
    std::size_t triangles = 0;
    if (rmb) {
      write_file_atomically(path, encode_rmb(p.grammar));
    } else {
      triangles = write_mesh(tree, path, name, a.format == "glb" || a.format == "gltf", up);
    }
    if (!global.quiet) {
      std::printf("%s: seed %llu, %zu axiom argument(s) perturbed, %zu nodes", path.c_str(),
                  static_cast<unsigned long long>(p.seed), p.perturbed_args, tree.size());
      if (!rmb) std::printf(", %zu triangles", triangles);
      std::printf("\n");
    }
  }
  return 0;
}

}  // namespace

void add_propagate(CLI::App& app, const GlobalOptions& global, std::function<int()>& run) {
  auto args = std::make_shared<PropagateArgs>();
  CLI::App* sub = app.add_subcommand(
      "propagate", "K distinct trees from one grammar by perturbing its axiom and seed");
  sub->add_option("file", args->grow.file, "grammar file (.ramus)")->required();
  sub->add_option("-n,--count", args->count, "number of trees K")
      ->required()
      ->check(CLI::Range(1, 100000));
  output_path(sub->add_option("-o,--output", args->dir, "output folder (tree_000.<format>, ...)"))
      ->required();
  sub->add_option("--seed", args->seed, "propagation seed (default: the grammar's seed)");
  sub->add_option("--jitter", args->jitter,
                  "relative perturbation of the axiom's numeric arguments, in [0, 1) (default 0.1)")
      ->check(CLI::Range(0.0, 0.999999));
  sub->add_option("--steps", args->steps, "derivation steps (default: the grammar's derive)")
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--format", args->format,
                  "what to write per tree: a mesh (glb, gltf, obj, ply) or the grammar (rmb)")
      ->check(CLI::IsMember({"glb", "gltf", "obj", "ply", "rmb"}));
  add_up_option(sub, args->up);
  sub->add_option("-D,--define", args->grow.defines, "override a param: name=value");
  sub->add_option("--system", args->grow.system, "lsystem block (default: the first)");
  sub->add_option("--max-modules", args->grow.max_modules, "stop with an error above this length");
  add_max_memory_option(sub, args->grow.max_memory);
  sub->callback(
      [args, &global, &run] { run = [args, &global] { return run_propagate(*args, global); }; });
}

}  // namespace ramus::cli
