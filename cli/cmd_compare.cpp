// ramus compare A B [--seeds N] [--seed S] [--tree-index T] [--reconstruct bsg|flood] [--voxel V]
// Compares the skeletons of two sources -- grammars (.ramus, grown over N seeds), skeleton files
// (.json) or scans (reconstructed) -- by the two-sample Kolmogorov-Smirnov distance of their
// distributions of branch length, branching angle, azimuth, radius ratio, branch order, total
// length, crown extent and height (docs/skeleton-inference.md, "Fidelity").
#include <cstdio>
#include <memory>

#include "cli/command.h"
#include "cli/skeleton_source.h"
#include "infer/skeleton/branch_rules.h"
#include "infer/skeleton/fidelity.h"

namespace ramus::cli {

namespace {

struct CompareArgs {
  std::string a, b;
  int seeds = 10;
  std::uint64_t seed = 1;
  int tree_index = -1;
  ReconstructChoice reconstruct;  // scans: as `ramus infer --method skeleton` reconstructs them
};

skeleton_infer::Distributions measure_source(const std::string& path, const CompareArgs& args,
                                             const GlobalOptions& global) {
  SkeletonSourceOptions so;
  so.seeds = args.seeds;
  so.first_seed = args.seed;
  so.tree_index = args.tree_index;
  so.quiet = global.quiet;
  so.reconstruct = args.reconstruct;
  skeleton_infer::Distributions d;
  for (const Skeleton& s : load_skeleton_source(path, so)) {
    try {
      skeleton_infer::measure(s, d);
    } catch (const skeleton_infer::ExtractError& e) {
      throw UserError(path + ": invalid skeleton: " + e.what());
    }
  }
  if (d.trees == 0) throw UserError(path + ": no tree with a segment to measure");
  return d;
}

int run_compare(const CompareArgs& args, const GlobalOptions& global) {
  const skeleton_infer::Distributions a = measure_source(args.a, args, global);
  const skeleton_infer::Distributions b = measure_source(args.b, args, global);
  std::printf("%-16s %8s %8s %12s %12s %7s\n", "measure", "n(A)", "n(B)", "mean(A)", "mean(B)",
              "KS");
  double worst = 0;
  for (const skeleton_infer::MeasureComparison& c : skeleton_infer::compare(a, b)) {
    std::printf("%-16s %8zu %8zu %12.4f %12.4f %7.4f\n", skeleton_infer::measure_name(c.measure),
                c.count_a, c.count_b, c.mean_a, c.mean_b, c.ks);
    worst = std::max(worst, c.ks);
  }
  std::printf("trees: A %zu, B %zu; largest KS %.4f\n", a.trees, b.trees, worst);
  return 0;
}

}  // namespace

void add_compare(CLI::App& app, const GlobalOptions& global, std::function<int()>& run) {
  auto args = std::make_shared<CompareArgs>();
  CLI::App* sub =
      app.add_subcommand("compare", "compare two skeleton sources by Kolmogorov-Smirnov distances");
  sub->add_option("A", args->a, "grammar (.ramus), skeleton (.json) or scan")->required();
  sub->add_option("B", args->b, "grammar (.ramus), skeleton (.json) or scan")->required();
  sub->add_option("--seeds", args->seeds, "trees grown from each grammar (default 10)")
      ->check(CLI::Range(1, 10000));
  sub->add_option("--seed", args->seed, "seed of the first grown tree (default 1)");
  sub->add_option("--tree-index", args->tree_index,
                  "the tree of a scan to use (default: the one with the most length)")
      ->check(CLI::NonNegativeNumber);
  add_reconstruct_choice_options(*sub, args->reconstruct, "--reconstruct", "scans: ");
  sub->callback(
      [args, &global, &run] { run = [args, &global] { return run_compare(*args, global); }; });
}

}  // namespace ramus::cli
