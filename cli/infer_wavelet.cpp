// ramus infer SCAN -o OUT.ramus --method wavelet [--grid 64] [--axiom-level j]
//     [--offset exact|scaled] [--scanner x,y,z]
// Friedman & Stamos 2013: one grammar with the voxel grammar (a `voxels` block), the L-rules of
// the wavelet progression with rule-space selection (an `lsystem` block) and one dyad's joined tree
// as the axiom (infer/wavelet/infer_grammar.h). Prints the compression figures, the rule counts and
// the time of each stage.
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "cli/infer_methods.h"
#include "cli/scan_args.h"
#include "core/atomic_file.h"
#include "infer/wavelet/infer_grammar.h"

namespace ramus::cli {

namespace {

struct WaveletArgs {
  int grid = 64;
  int axiom_level = -1;  // -1: the default of infer_wavelet_grammar
  std::string offset = "scaled";
  std::string scanner;
};

std::string block_name(const std::string& path) {
  std::string base = file_name(path);
  const std::size_t dot = base.find('.');
  if (dot != std::string::npos) base.resize(dot);
  std::string out;
  for (char c : base) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    out += ok ? c : '_';
  }
  if (out.empty() || (out[0] >= '0' && out[0] <= '9')) out = "scan_" + out;
  return out;
}

void print_result(const wavelet::WaveletInference& r, const InferCommonArgs& common) {
  const auto& c = r.compression;
  std::printf("%s: %zu points -> %zu^3 grid, %zu occupied voxels\n",
              file_name(common.input).c_str(), r.points, r.grid_side, r.occupied_voxels);
  std::printf("compression: lossless %.1f%%  lossy %.1f%%  lossy IoU %.3f\n",
              100 * c.lossless_ratio, 100 * c.lossy_ratio, c.lossy_iou);
  std::printf("voxel rules: %zu\n", r.voxel_rules);
  std::printf("spanning-tree vectors: %zu (per dyad:", r.dyad_vectors);
  for (std::size_t n : r.vectors_per_dyad) std::printf(" %zu", n);
  std::printf(")\n");
  std::printf("L-rules: %zu, productions: %zu, axiom: dyad %d (%zu vectors)\n", r.l_rules,
              r.productions, r.axiom_level, r.axiom_vectors);
  std::printf("time:");
  for (const wavelet::StageTiming& t : r.timings)
    std::printf(" %s %.3f s,", t.stage.c_str(), t.seconds);
  std::printf(" total %.3f s\n", r.total_seconds);
  std::printf("wrote %s\n", common.output.c_str());
}

int run_wavelet(const WaveletArgs& a, const InferCommonArgs& common, const GlobalOptions& global) {
  wavelet::WaveletInferOptions o;
  o.grid = a.grid;
  if (a.axiom_level >= 0) o.axiom_level = a.axiom_level;
  o.seed = common.seed;
  o.name = block_name(common.input);
  o.source = file_name(common.input);
  try {  // the options are checked before the scan is read
    o.offset = wavelet::parse_l_rule_offset(a.offset);
    wavelet::validate_options(o);
  } catch (const std::invalid_argument& e) {
    throw UserError(e.what());
  }
  const AlignedScan scan = read_aligned_scan(common.input, a.scanner, "infer", global.quiet);
  wavelet::WaveletInference r;
  try {
    r = wavelet::infer_wavelet_grammar(scan.aligned, o);
  } catch (const std::invalid_argument& e) {
    throw UserError(common.input + ": " + e.what());
  }
  write_file_atomically(common.output, r.ramus_text);
  // The alignment's own warning was printed when the scan was read.
  for (const std::string& w : r.warnings) {
    if (w != scan.aligned.alignment.warning && !global.quiet) {
      std::fprintf(stderr, "ramus infer: warning: %s\n", w.c_str());
    }
  }
  if (!global.quiet) print_result(r, common);
  return 0;
}

}  // namespace

InferRunner add_infer_wavelet_options(CLI::App& cmd, const GlobalOptions& global) {
  auto args = std::make_shared<WaveletArgs>();
  cmd.add_option("--grid", args->grid,
                 "wavelet: voxel grid side, a power of two from 4 to 256 (default 64)");
  cmd.add_option("--axiom-level", args->axiom_level,
                 "wavelet: the dyad whose tree is the axiom (default: the second finest)");
  cmd.add_option("--offset", args->offset,
                 "wavelet: L-rule box offset, exact (Eq. 1-3 as written) or scaled (default)")
      ->check(CLI::IsMember({"exact", "scaled"}));
  cmd.add_option("--scanner", args->scanner,
                 "wavelet: scanner position x,y,z (default: from the file)");
  return
      [args, &global](const InferCommonArgs& common) { return run_wavelet(*args, common, global); };
}

}  // namespace ramus::cli
