// ramus infer INPUT -o OUT.ramus --method skeleton [--model scaffold|clustered]
//                   [--limb-share S] [--max-rules N] [--clusters K] [--max-order O]
//                   [--tree-index T] [--merge alpha,beta] [--reconstruct bsg|flood] [--voxel V]
//                   [--write-skeleton S.json]
// Skeleton -> parametric L-system (docs/skeleton-inference.md): by default the tree's scaffold
// as measured with shoots grown from species-level params (scaffold_grammar.h); with
// --model clustered, clustered stochastic rules for every internode (skeleton_grammar.h). INPUT
// is a scan (reconstructed first), a skeleton file (.json) or a grammar (.ramus, grown with
// --seed).
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli/infer_methods.h"
#include "cli/output_path.h"
#include "cli/skeleton_source.h"
#include "core/atomic_file.h"
#include "formats/skeleton_json.h"
#include "infer/skeleton/scaffold_grammar.h"
#include "infer/skeleton/skeleton_grammar.h"
#include "reconstruct/merge/branch_merge.h"

namespace ramus::cli {

namespace {

struct SkeletonInferArgs {
  std::string model = "scaffold";  // scaffold | clustered
  double limb_share = 0.01;        // scaffold: --limb-share
  std::vector<CLI::Option*> clustered_only, scaffold_only;
  int max_rules = 32;
  int clusters = 4;
  int max_order = 3;
  int tree_index = -1;
  int calibration_seeds = 32;
  bool no_tropism = false;
  bool no_axis_budget = false;
  std::string axis_ends = "auto";  // auto | own | shared
  std::string merge;               // "alpha,beta" in degrees; empty: no merging
  ReconstructChoice reconstruct;   // scans: --reconstruct, --voxel
  std::string skeleton_out;        // --write-skeleton: the skeleton the grammar is inferred from
};

merge::MergeOptions parse_merge(const std::string& text) {
  const auto comma = text.find(',');
  merge::MergeOptions o;
  try {
    if (comma == std::string::npos) throw std::invalid_argument(text);
    std::size_t used = 0;
    o.alpha_deg = std::stod(text.substr(0, comma), &used);
    if (used != comma) throw std::invalid_argument(text);
    const std::string beta = text.substr(comma + 1);
    o.beta_deg = std::stod(beta, &used);
    if (used != beta.size()) throw std::invalid_argument(text);
  } catch (const std::exception&) {
    throw UserError("--merge takes two angles in degrees, alpha,beta (e.g. 10,15); got '" + text +
                    "'");
  }
  if (!(o.alpha_deg >= 0) || !(o.beta_deg >= 0)) {
    throw UserError("--merge angles must be non-negative numbers; got '" + text + "'");
  }
  return o;
}

// Runs one model's inference and writes its text to the output; its errors name the input.
template <class Infer>
auto infer_and_write(const InferCommonArgs& common, const Infer& infer) {
  try {
    auto g = infer();
    write_file_atomically(common.output, g.text);
    return g;
  } catch (const skeleton_infer::ExtractError& e) {
    throw UserError(common.input + ": invalid skeleton: " + e.what());
  } catch (const skeleton_infer::InferError& e) {
    throw UserError(common.input + ": " + e.what());
  } catch (const WriteError& e) {
    throw UserError(e.what());
  }
}

// The default model: the scaffold as measured and shoots grown from species-level params.
int write_scaffold_grammar(const InferCommonArgs& common, const SkeletonInferArgs& a,
                           const Skeleton& skeleton, const GlobalOptions& global) {
  skeleton_infer::ScaffoldGrammarOptions so;
  so.scaffold.min_share = a.limb_share;
  so.tropism = !a.no_tropism;
  so.seed = common.seed;
  so.source_name = std::filesystem::path(common.input).filename().string();
  const skeleton_infer::ScaffoldGrammar g =
      infer_and_write(common, [&] { return skeleton_infer::infer_scaffold_grammar(skeleton, so); });
  if (!global.quiet) {
    const skeleton_infer::SpeciesParams& p = g.params;
    std::printf(
        "%s: scaffold of %zu axes (%zu segments) and %zu shoots from %zu internodes; %zu "
        "productions, derive %d\n",
        common.output.c_str(), g.scaffold_axes, g.scaffold_segments, g.buds, g.internodes,
        g.productions, g.steps);
    std::printf(
        "  branch angle %.1f (sd %.1f), kink %.1f, lateral side %.1f, lateral share %.3f, "
        "elasticity %.4f (%zu pairs, R^2 %.2f)\n",
        p.branch_angle, p.branch_angle_sd, p.kink_angle, p.lateral_side, p.lateral_share,
        p.elasticity, g.tropism.pairs, g.tropism.r2);
  }
  return 0;
}

int run_skeleton_infer(const InferCommonArgs& common, const SkeletonInferArgs& a,
                       const GlobalOptions& global) {
  // Options of the other model are errors before any work (a reconstruction can take minutes).
  const bool scaffold = a.model == "scaffold";
  for (const CLI::Option* o : scaffold ? a.clustered_only : a.scaffold_only) {
    if (o->count() > 0)
      throw UserError(o->get_name() + " applies to --model " +
                      (scaffold ? "clustered" : "scaffold") + " only");
  }
  SkeletonSourceOptions so;
  so.first_seed = common.seed;  // a grammar (.ramus) is grown once with this seed
  so.tree_index = a.tree_index;
  so.quiet = global.quiet;
  so.reconstruct = a.reconstruct;
  Skeleton skeleton = std::move(load_skeleton_source(common.input, so).front());
  if (!a.merge.empty()) {
    const merge::MergeOptions mo = parse_merge(a.merge);
    try {
      const merge::MergeStats ms = merge::merge_branches(skeleton, mo);
      if (!global.quiet) {
        std::fprintf(stderr,
                     "ramus: merged branches: %zu -> %zu nodes (%zu vertical, %zu horizontal)\n",
                     ms.nodes_before, ms.nodes_after, ms.vertical_merges, ms.horizontal_merges);
      }
    } catch (const std::invalid_argument& e) {
      throw UserError(std::string("--merge: ") + e.what());
    }
  }
  if (!a.skeleton_out.empty()) {
    try {
      write_skeleton_json(a.skeleton_out, skeleton);
    } catch (const std::exception& e) {
      throw UserError(a.skeleton_out + ": " + e.what());
    }
  }
  if (a.model == "scaffold") return write_scaffold_grammar(common, a, skeleton, global);
  skeleton_infer::GrammarOptions go;
  go.max_rules = a.max_rules;
  go.cluster.max_clusters = a.clusters;
  go.cluster.max_order = a.max_order;
  go.cluster.seed = common.seed;
  go.calibration_seeds = a.calibration_seeds;
  go.tropism = !a.no_tropism;
  go.axis_budget = !a.no_axis_budget;
  using AxisEnds = skeleton_infer::GrammarOptions::AxisEnds;
  go.axis_ends = a.axis_ends == "own"      ? AxisEnds::own
                 : a.axis_ends == "shared" ? AxisEnds::shared
                                           : AxisEnds::automatic;
  go.source_name = std::filesystem::path(common.input).filename().string();
  const skeleton_infer::InferredGrammar g =
      infer_and_write(common, [&] { return skeleton_infer::infer_grammar(skeleton, go); });
  if (!global.quiet) {
    std::printf(
        "%s: %zu productions, %zu alternatives from %zu internodes (%zu branch nodes), "
        "derive %d, tortuosity %.3f, calibration shift %.3f, elasticity %.4f (%zu pairs, R^2 "
        "%.2f)\n",
        common.output.c_str(), g.productions, g.alternatives, g.internodes, g.branch_nodes,
        g.derive, g.tortuosity, g.tip_shift, g.tropism.elasticity, g.tropism.pairs, g.tropism.r2);
    if (go.axis_budget) {
      std::printf("  axis ends: %s",
                  g.axis_ends == skeleton_infer::GrammarOptions::AxisEnds::own ? "own" : "shared");
      if (g.distance_own >= 0)
        std::printf(" (grown distance to the input: own %.3f, shared %.3f)", g.distance_own,
                    g.distance_shared);
      std::printf("\n");
    }
    for (const auto& grp : g.groups) {
      std::printf("  order %u%s arity %u%s: %zu rules -> %zu cluster(s)\n", unsigned(grp.order),
                  grp.order == a.max_order ? "+" : "", grp.arity, grp.last ? " (axis ends)" : "",
                  grp.count, grp.clusters.size());
    }
  }
  return 0;
}

}  // namespace

InferRunner add_infer_skeleton_options(CLI::App& cmd, const GlobalOptions& global) {
  auto a = std::make_shared<SkeletonInferArgs>();
  cmd.add_option("--model", a->model,
                 "skeleton: scaffold (the trunk and main limbs as measured, shoots grown from "
                 "species-level params; default) or clustered (every internode from clustered "
                 "stochastic rules)")
      ->check(CLI::IsMember({"scaffold", "clustered"}));
  a->scaffold_only.push_back(
      cmd.add_option("--limb-share", a->limb_share,
                     "skeleton, scaffold: a lateral axis joins the scaffold when it carries at "
                     "least this share of the tree's length (default 0.01)")
          ->check(CLI::Range(0.0, 1.0)));
  a->clustered_only.push_back(
      cmd.add_option(
             "--max-rules", a->max_rules,
             "skeleton, clustered: most stochastic alternatives in the grammar (default 32)")
          ->check(CLI::Range(2, 1000)));
  a->clustered_only.push_back(
      cmd.add_option("--clusters", a->clusters,
                     "skeleton, clustered: most clusters per order and arity, chosen by "
                     "silhouette (default 4)")
          ->check(CLI::Range(1, 64)));
  a->clustered_only.push_back(
      cmd.add_option("--max-order", a->max_order,
                     "skeleton, clustered: branch orders from this one on share productions "
                     "(default 3)")
          ->check(CLI::Range(0, 100)));
  cmd.add_option("--tree-index", a->tree_index,
                 "skeleton: the tree of the scan to use (default: the one with the most length)")
      ->check(CLI::NonNegativeNumber);
  a->clustered_only.push_back(
      cmd.add_option("--calibrate", a->calibration_seeds,
                     "skeleton: fit the tip hazards to the input's total length over N grown seeds "
                     "(default 32; 0: off)")
          ->check(CLI::Range(0, 100)));
  a->clustered_only.push_back(cmd.add_flag(
      "--no-axis-budget", a->no_axis_budget,
      "skeleton, clustered: end axes by a tip hazard per internode instead of a length budget "
      "per axis"));
  a->clustered_only.push_back(
      cmd.add_option(
             "--axis-ends", a->axis_ends,
             "skeleton: how budgeted axes end: own (tips and last branch nodes of their own), "
             "shared (one length model for every internode), auto (both grown, the closer "
             "to the input kept; default)")
          ->check(CLI::IsMember({"auto", "own", "shared"})));
  cmd.add_flag("--no-tropism", a->no_tropism,
               "skeleton: do not fit a gravitropism (every internode's turn drawn independently)");
  cmd.add_option("--merge", a->merge,
                 "skeleton: merge branches first, alpha,beta in degrees (vertical, horizontal)");
  add_reconstruct_choice_options(cmd, a->reconstruct, "--reconstruct", "skeleton, scans: ");
  output_path(cmd.add_option(
      "--write-skeleton", a->skeleton_out,
      "skeleton: also write the skeleton the grammar is inferred from (.json); for a "
      "scan, its reconstruction), to compare the grammar against it"));
  return [a, &global](const InferCommonArgs& common) {
    return run_skeleton_infer(common, *a, global);
  };
}

}  // namespace ramus::cli
