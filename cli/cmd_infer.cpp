// ramus infer INPUT -o OUT.ramus --method wavelet|skeleton [method options]
// Infers a grammar from a scan. The methods live in infer_wavelet.cpp and infer_skeleton.cpp;
// this file holds the options they share and dispatches on --method.
#include <memory>

#include "cli/command.h"
#include "cli/infer_methods.h"
#include "cli/output_path.h"

namespace ramus::cli {

void add_infer(CLI::App& app, const GlobalOptions& global, std::function<int()>& run) {
  auto args = std::make_shared<InferCommonArgs>();
  CLI::App* sub = app.add_subcommand("infer", "infer a grammar from a scan");
  sub->add_option("INPUT", args->input,
                  "point cloud (.ply .xyz .txt .asc .las .laz .pcd); --method skeleton also "
                  "takes a skeleton .json or a .ramus grammar")
      ->required();
  output_path(sub->add_option("-o,--output", args->output, "the grammar to write (.ramus)"))
      ->required();
  sub->add_option("--method", args->method, "inference method (required)")
      ->required()
      ->check(CLI::IsMember({"wavelet", "skeleton"}));
  sub->add_option("--seed", args->seed, "seed of every random choice (default 1)");
  InferRunner wavelet = add_infer_wavelet_options(*sub, global);
  InferRunner skeleton = add_infer_skeleton_options(*sub, global);
  run = [args, wavelet, skeleton] {
    return args->method == "wavelet" ? wavelet(*args) : skeleton(*args);
  };
}

}  // namespace ramus::cli
