// ramus merge DIR -o forest.json|.glb|.gltf|.obj|.ply [--up y|z]
// Joins the per-tile reconstructions of a tiled plot (DIR/K.json for every tile K of
// DIR/manifest.json, written by `ramus reconstruct DIR/manifest.json --tile K`) into one forest in
// the original coordinates: one root per tree. Each tile kept only the trees based in its core and
// the cores partition the plane, so no tree comes twice; merge checks that it is so.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli/command.h"
#include "cli/mesh_output.h"
#include "cli/output_path.h"
#include "cli/skeleton_output.h"
#include "core/skeleton_trees.h"
#include "formats/skeleton_json.h"
#include "formats/tile_manifest.h"

namespace ramus::cli {
namespace {

struct MergeArgs {
  std::string dir, output, up;
};

int run_merge(const MergeArgs& a, const GlobalOptions& global) {
  const mesh::UpAxis up = mesh_up_axis(a.up, a.output);
  const std::filesystem::path dir(a.dir);
  TileManifest m;
  try {
    m = read_tile_manifest((dir / "manifest.json").string());
  } catch (const FormatError& e) {
    throw UserError(e.what());
  }
  std::string missing;
  for (const TileEntry& t : m.tiles) {
    if (!std::filesystem::exists(dir / (std::to_string(t.id) + ".json"))) {
      missing += (missing.empty() ? "" : ", ") + std::to_string(t.id);
    }
  }
  if (!missing.empty()) {
    throw UserError(a.dir + ": tile(s) " + missing + " not reconstructed yet (ramus reconstruct " +
                    (dir / "manifest.json").string() + " --tile K -o " + (dir / "K.json").string() +
                    ")");
  }
  std::vector<Skeleton> trees;
  std::vector<std::pair<Vec3, int>> bases;  // base and tile of every tree, for the checks
  for (const TileEntry& t : m.tiles) {
    const std::string path = (dir / (std::to_string(t.id) + ".json")).string();
    Skeleton s;
    try {
      s = read_skeleton_json(path);
    } catch (const FormatError& e) {
      throw UserError(e.what());
    }
    for (Skeleton& tree : split_trees(s)) {
      const Vec3 b = tree.nodes[tree.roots().front()].position;
      if (!t.core.contains(b.x, b.y)) {
        char msg[200];
        std::snprintf(msg, sizeof msg,
                      ": the tree based at (%.3f, %.3f) lies outside tile %d's core: not the "
                      "output of `ramus reconstruct --tile %d`?",
                      b.x, b.y, t.id, t.id);
        throw UserError(path + msg);
      }
      bases.push_back({b, t.id});
      trees.push_back(std::move(tree));
    }
  }
  // No tree twice: two bases at one place (a tile file copied over another, say).
  std::vector<std::size_t> order(bases.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t i, std::size_t j) { return bases[i].first.x < bases[j].first.x; });
  for (std::size_t k = 0; k < order.size(); ++k) {
    for (std::size_t l = k + 1; l < order.size(); ++l) {
      const Vec3 &p = bases[order[k]].first, &q = bases[order[l]].first;
      if (q.x - p.x > 1e-3) break;
      if (std::abs(q.y - p.y) <= 1e-3) {
        throw UserError(a.dir + ": tiles " + std::to_string(bases[order[k]].second) + " and " +
                        std::to_string(bases[order[l]].second) + " hold the same tree");
      }
    }
  }
  write_skeleton_output(join_trees(trees), a.output, "forest", up);
  if (!global.quiet) {
    std::fprintf(stderr, "ramus: wrote %s (%zu trees from %zu tiles)\n", a.output.c_str(),
                 trees.size(), m.tiles.size());
  }
  return 0;
}

}  // namespace

void add_merge(CLI::App& app, const GlobalOptions& global, std::function<int()>& run) {
  auto args = std::make_shared<MergeArgs>();
  CLI::App* sub = app.add_subcommand(
      "merge", "join the tiles' reconstructions (ramus tile, reconstruct --tile) into one forest");
  sub->add_option("dir", args->dir, "the tiles' folder: manifest.json and K.json per tile")
      ->required()
      ->check(CLI::ExistingDirectory);
  output_path(sub->add_option("-o,--output", args->output,
                              "output: .json (one root per tree), .glb, .gltf, .obj or .ply"))
      ->required()
      ->check(CLI::Validator(check_skeleton_output, "FILE", "output file"));
  add_up_option(sub, args->up);
  sub->callback(
      [args, &global, &run] { run = [args, &global] { return run_merge(*args, global); }; });
}

}  // namespace ramus::cli
