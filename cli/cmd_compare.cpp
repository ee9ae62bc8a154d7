// ramus compare A B [--seeds N] [--seed S] [--tree-index T] [--reconstruct bsg|flood] [--voxel V]
//                   [--within D,...] [--picture OUT.png [--picture-also C]...]
// Compares the skeletons of two sources -- grammars (.ramus or .rmb, grown over N seeds),
// skeleton files (.json) or scans (reconstructed). First the shape of B's trees against A:
// envelope IoU (with the reconstruction's own as the reference line when A is a scan), pieces,
// axis-locked share, height ratio and trunk lean (docs/shape-measures.md); then the two-sample
// Kolmogorov-Smirnov distance of their distributions of branch length, branching angle, azimuth,
// radius ratio, branch order, total length, crown extent and height (docs/skeleton-inference.md,
// "Fidelity"). With --within, between the two: the share of B's skeleton within each distance of
// A's and of A's within it of B's, for a reconstruction against a reference skeleton of the same
// tree (cli/compare_distance.h).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli/command.h"
#include "cli/compare_distance.h"
#include "cli/compare_picture.h"
#include "cli/compare_shape.h"
#include "cli/compare_side.h"
#include "cli/output_path.h"
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
  std::string picture;
  std::vector<std::string> picture_also;  // more grammars or skeletons drawn after B
  std::vector<double> within;             // distances of the positional comparison
  // Which options the user gave, to refuse those that do not apply to the sources.
  bool given_seeds = false, given_scan_options = false;
};

skeleton_infer::Distributions measure_side(const CompareSide& side) {
  skeleton_infer::Distributions d;
  for (const Skeleton& s : side.trees) {
    try {
      skeleton_infer::measure(s, d);
    } catch (const skeleton_infer::ExtractError& e) {
      throw UserError(side.path + ": invalid skeleton: " + e.what());
    }
  }
  if (d.trees == 0) throw UserError(side.path + ": no tree with a segment to measure");
  return d;
}

// Options that would be silently ignored are errors, so a user never believes they took effect.
void check_options(const CompareArgs& args) {
  const SourceKind ka = source_kind(args.a), kb = source_kind(args.b);
  auto any = [&](SourceKind k) { return ka == k || kb == k; };
  if (args.given_seeds && !any(SourceKind::Grammar)) {
    throw UserError(
        "--seeds and --seed grow grammars, and neither source is a grammar (.ramus or .rmb)");
  }
  if (args.given_scan_options && !any(SourceKind::Scan)) {
    throw UserError(
        "--tree-index, --reconstruct and --voxel apply to scans, and neither source is a scan");
  }
  if (!args.within.empty() && (ka == SourceKind::Grammar || kb == SourceKind::Grammar)) {
    throw UserError(
        "--within measures a skeleton against a reference skeleton of the same tree, and a "
        "grammar's grown trees are not that tree: give skeleton files (.json) or scans");
  }
  if (args.picture.empty() && !args.picture_also.empty())
    throw UserError("--picture-also adds trees to --picture, and there is no --picture");
  if (!args.picture.empty()) {
    if (!any(SourceKind::Scan) && !any(SourceKind::Grammar)) {
      throw UserError(
          "--picture draws a scan or a grammar's trees, and both sources are skeleton "
          "files (.json); use `ramus preview` on a grammar instead");
    }
    for (const std::string& c : args.picture_also) {
      if (source_kind(c) == SourceKind::Scan)
        throw UserError("--picture-also draws a grammar's trees or a skeleton file, not a scan: " +
                        c);
    }
    const std::string ext = std::filesystem::path(args.picture).extension().string();
    if (ext != ".png") throw UserError("--picture writes a .png file, not " + args.picture);
  }
}

int run_compare(const CompareArgs& args, const GlobalOptions& global) {
  check_options(args);
  SkeletonSourceOptions so;
  so.seeds = args.seeds;
  so.first_seed = args.seed;
  so.tree_index = args.tree_index;
  so.quiet = global.quiet;
  so.reconstruct = args.reconstruct;
  const CompareSide side_a = load_compare_side(args.a, so);
  const CompareSide side_b = load_compare_side(args.b, so);
  const skeleton_infer::Distributions a = measure_side(side_a);
  const skeleton_infer::Distributions b = measure_side(side_b);

  // The shape section comes first so that the branch-statistics table ends the output, as
  // scripts that read it from its header to the end expect.
  print_shape_report(measure_shapes(side_a, side_b));
  if (!args.within.empty()) {
    std::vector<double> within = args.within;
    std::sort(within.begin(), within.end());
    print_distance_report(measure_distances(side_a, side_b, within));
  }

  std::printf("%-16s %8s %8s %12s %12s %7s\n", "measure", "n(A)", "n(B)", "mean(A)", "mean(B)",
              "KS");
  double worst = 0;
  for (const skeleton_infer::MeasureComparison& c : skeleton_infer::compare(a, b)) {
    std::printf("%-16s %8zu %8zu %12.4f %12.4f %7.4f\n", skeleton_infer::measure_name(c.measure),
                c.count_a, c.count_b, c.mean_a, c.mean_b, c.ks);
    worst = std::max(worst, c.ks);
  }
  std::printf("trees: A %zu, B %zu; largest KS %.4f\n", a.trees, b.trees, worst);
  if (!args.picture.empty()) {
    std::vector<CompareSide> also;
    for (const std::string& c : args.picture_also) also.push_back(load_compare_side(c, so));
    std::vector<const CompareSide*> sides{&side_a, &side_b};
    for (const CompareSide& s : also) sides.push_back(&s);
    write_compare_picture(args.picture, sides);
    if (!global.quiet) std::fprintf(stderr, "ramus: wrote %s\n", args.picture.c_str());
  }
  return 0;
}

}  // namespace

void add_compare(CLI::App& app, const GlobalOptions& global, std::function<int()>& run) {
  auto args = std::make_shared<CompareArgs>();
  CLI::App* sub = app.add_subcommand(
      "compare",
      "compare two skeleton sources: envelope IoU, tree shape and Kolmogorov-Smirnov distances");
  sub->add_option("A", args->a, "the reference: scan, grammar (.ramus) or skeleton (.json)")
      ->required();
  sub->add_option("B", args->b, "grammar (.ramus), skeleton (.json) or scan")->required();
  sub->add_option("--seeds", args->seeds, "trees grown from each grammar (default 10)")
      ->check(CLI::Range(1, 10000));
  sub->add_option("--seed", args->seed, "seed of the first grown tree (default 1)");
  sub->add_option("--tree-index", args->tree_index,
                  "the tree of a scan to use (default: the one with the most length)")
      ->check(CLI::NonNegativeNumber);
  add_reconstruct_choice_options(*sub, args->reconstruct, "--reconstruct", "scans: ");
  sub->add_option("--within", args->within,
                  "distances (the sources' units), comma-separated, e.g. 0.05,0.1,0.2: the share "
                  "of B's skeleton within each of reference A's (precision) and of A's within it "
                  "of B's (recall); skeleton files or scans of the same tree only")
      ->delimiter(',')
      ->check(CLI::PositiveNumber);
  output_path(sub->add_option(
      "--picture", args->picture,
      "also draw the scan, its reconstruction and the first 3 grown trees, front and "
      "side (.png)"));
  sub->add_option("--picture-also", args->picture_also,
                  "with --picture: also draw the first 3 trees of this grammar (or the tree of "
                  "this skeleton file) after B's, in another colour (repeatable)");
  sub->footer(
      "A is the reference. Printed: the envelope IoU of B's trees against A (a scan's own "
      "reconstruction first, as the reference line), pieces, axis-locked share, height ratio "
      "and trunk lean per tree (docs/shape-measures.md), with --within the share of B's skeleton "
      "within each distance of A's and the converse (docs/reconstruction.md, Accuracy), then "
      "the KS distances "
      "(docs/skeleton-inference.md, Fidelity). Options that do not apply to the sources are "
      "errors.");
  sub->callback([args, sub, &global, &run] {
    args->given_seeds = sub->count("--seeds") + sub->count("--seed") > 0;
    args->given_scan_options =
        sub->count("--tree-index") + sub->count("--reconstruct") + sub->count("--voxel") > 0;
    run = [args, &global] { return run_compare(*args, global); };
  });
}

}  // namespace ramus::cli
