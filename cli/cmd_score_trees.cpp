// ramus score-trees TRUTH.json FOREST.json [--match D]
// Tree detection quality of a reconstructed forest against the truth of a simulated plot
// (`ramus scan --forest --truth`): matched, missed, merged, split and false trees, precision,
// recall and F-score (reconstruct/forest/detection_score.h; docs/scale.md).
#include <cstdio>
#include <memory>

#include "cli/command.h"
#include "core/skeleton_trees.h"
#include "formats/skeleton_json.h"
#include "reconstruct/forest/detection_score.h"

namespace ramus::cli {
namespace {

struct ScoreArgs {
  std::string truth, forest;
  double match = 0.5;
};

std::vector<Skeleton> read_trees(const std::string& path) {
  try {
    return split_trees(read_skeleton_json(path));
  } catch (const FormatError& e) {
    throw UserError(e.what());
  }
}

int run_score_trees(const ScoreArgs& a) {
  const forest::DetectionScore s =
      forest::score_detection(read_trees(a.truth), read_trees(a.forest), a.match);
  std::printf("truth trees     %zu\n", s.truth);
  std::printf("detected trees  %zu\n", s.detected);
  std::printf("matched         %zu (bases within %g m; mean %.3f m, max %.3f m)\n", s.matched,
              a.match, s.mean_base_error, s.max_base_error);
  std::printf("missed          %zu\n", s.missed);
  std::printf("merged          %zu\n", s.merged);
  std::printf("split           %zu\n", s.split);
  std::printf("false           %zu\n", s.false_trees);
  std::printf("precision       %.3f\nrecall          %.3f\nF-score         %.3f\n", s.precision,
              s.recall, s.f_score);
  return 0;
}

}  // namespace

void add_score_trees(CLI::App& app, const GlobalOptions&, std::function<int()>& run) {
  auto args = std::make_shared<ScoreArgs>();
  CLI::App* sub = app.add_subcommand(
      "score-trees", "tree detection against a plot's truth: matched, missed, merged, split, F");
  sub->add_option("truth", args->truth, "the truth: skeleton JSON, one root per tree")
      ->required()
      ->check(CLI::ExistingFile);
  sub->add_option("forest", args->forest, "the reconstruction: skeleton JSON, one root per tree")
      ->required()
      ->check(CLI::ExistingFile);
  sub->add_option("--match", args->match,
                  "largest distance between matched bases in metres (default 0.5)")
      ->check(CLI::PositiveNumber);
  sub->callback([args, &run] { run = [args] { return run_score_trees(*args); }; });
}

}  // namespace ramus::cli
