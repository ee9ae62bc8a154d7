// The whole wavelet inference of infer_grammar.h: every stage of Friedman & Stamos 2013 section
// III in order, timed, and the grammar text they produce.
#include "infer/wavelet/infer_grammar.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

#include "grammar/diagnostic.h"
#include "grammar/format.h"
#include "grammar/parser.h"
#include "grammar/source.h"
#include "infer/wavelet/dyad_tree.h"
#include "infer/wavelet/haar.h"
#include "infer/wavelet/isolated_points.h"
#include "infer/wavelet/lsystem_text.h"
#include "infer/wavelet/tree_hierarchy.h"
#include "infer/wavelet/tree_presence.h"
#include "infer/wavelet/voxel_grammar.h"

namespace ramus::wavelet {
namespace {

using Clock = std::chrono::steady_clock;

// Records how long each stage took, in the order the stages run.
class StageClock {
 public:
  explicit StageClock(std::vector<StageTiming>& out) : out_(out), start_(Clock::now()) {}
  void done(const char* stage) {
    const Clock::time_point now = Clock::now();
    out_.push_back({stage, std::chrono::duration<double>(now - start_).count()});
    start_ = now;
  }

 private:
  std::vector<StageTiming>& out_;
  Clock::time_point start_;
};

// Numbers in the header: 6 significant digits.
std::string num(double v, int digits = 6) {
  if (v == 0) return "0";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

// The text in `ramus fmt`'s layout (so `ramus fmt --check` accepts an inferred grammar). The
// text is built by this file, so a parse error is a bug here, not a user error.
std::string canonical_layout(const std::string& text) {
  SourceManager sm;
  DiagnosticSink sink;
  const std::uint32_t id = sm.add("inferred.ramus", text);
  const ast::File file = parse(sm, id, sink);
  if (sink.has_errors()) {
    throw std::logic_error("the inferred grammar does not parse: " + render_text(sm, sink.all()));
  }
  return format_file(file, sm);
}

int checked_levels(const WaveletInferOptions& o) {
  if (o.grid < 4 || o.grid > 256 || !is_power_of_two(std::uint64_t(o.grid))) {
    throw std::invalid_argument("--grid must be a power of two from 4 to 256, not " +
                                std::to_string(o.grid));
  }
  const int levels = levels_for_side(std::uint64_t(o.grid));
  if (o.axiom_level && (*o.axiom_level < 0 || *o.axiom_level >= levels)) {
    throw std::invalid_argument("--axiom-level must be a dyad of the " + std::to_string(o.grid) +
                                "^3 grid, from 0 to " + std::to_string(levels - 1) + ", not " +
                                std::to_string(*o.axiom_level));
  }
  if (!(o.mst_threshold > 0 && o.mst_threshold < 1)) {
    throw std::invalid_argument("the spanning-tree threshold must lie in (0, 1)");
  }
  return levels;
}

std::string voxels_block(const WaveletInferOptions& o, const VoxelGrammar& vg, std::size_t& count) {
  std::string out =
      "// Voxel grammar (III-C): a coefficient of one dyad -> its eight coefficients in\n"
      "// the next finer dyad (Morton order, x fastest), as quantization classes\n"
      "// (class " +
      std::to_string(vg.quantizer.zero_class()) +
      " is zero), weighted by how often the pair was observed.\n";
  out += "voxels " + o.name + "_voxels {\n";
  out += "  levels " + std::to_string(vg.levels) + ";\n";
  out += "  classes " + std::to_string(vg.quantizer.classes) + ";\n";
  out += "  seed " + std::to_string(o.seed) + ";\n";
  count = 0;
  for (const VoxelRule& r : vg.rules) {
    if (r.subband != kDiagonalSubband) continue;  // the dyads proper; the block has no subbands
    out += "  " + std::to_string(r.parent) + " -> [";
    for (int c = 0; c < 8; ++c) out += (c ? " " : "") + std::to_string(r.children[c]);
    out += "] x" + std::to_string(r.count) + ";\n";
    ++count;
  }
  return out + "}\n";
}

}  // namespace

void validate_options(const WaveletInferOptions& options) { (void)checked_levels(options); }

WaveletInference infer_wavelet_grammar(const AlignedCloud& input,
                                       const WaveletInferOptions& options) {
  const Clock::time_point t0 = Clock::now();
  const int levels = checked_levels(options);
  require_tree(input);  // a plane, a handful of points or one height: no tree to infer
  WaveletInference r;
  StageClock clock(r.timings);
  r.points = input.points.size();
  const std::optional<AlignedCloud> kept = without_isolated_points(input);
  const AlignedCloud& cloud = kept ? *kept : input;
  if (kept) {
    r.warnings.push_back("left out " + std::to_string(input.points.size() - kept->points.size()) +
                         " isolated point(s) with no other point within 1/16 of the scan's "
                         "extent");
  }

  // III-A: quantization.
  VoxelizeOptions vo;
  vo.levels = levels;
  vo.values = options.values;
  const VoxelGrid grid = voxelize(cloud, vo);
  r.grid_side = grid.n;
  r.occupied_voxels = grid.count_above(0);
  clock.done("voxelize");

  // III-B: the transforms; IV-A: Table I figures from the standard decomposition.
  const WaveletPyramid standard = haar_forward(grid, Decomposition::standard);
  const WaveletPyramid pyramid = haar_forward(grid, Decomposition::nonstandard);
  clock.done("haar");
  r.compression = compression_stats(grid, standard, options.gamma);
  clock.done("compression");

  // III-C: the voxel grammar.
  VoxelGrammarOptions vgo;
  vgo.classes = options.classes;
  const VoxelGrammar vg = learn_voxel_grammar(pyramid, vgo);
  clock.done("voxel grammar");

  // III-E: one spanning tree per dyad (the diagonal cube is the same in both decompositions).
  DyadTreeOptions to;
  to.threshold = options.mst_threshold;
  const std::vector<DyadTree> trees = dyad_trees(pyramid, to);
  std::vector<std::vector<DyadVector>> vectors;
  for (const DyadTree& t : trees) {
    vectors.push_back(dyad_vectors(t));
    r.vectors_per_dyad.push_back(vectors.back().size());
    r.dyad_vectors += vectors.back().size();
  }
  clock.done("spanning trees");

  // III-G: the axiom is one dyad's (joined) tree; by default the second finest, so that one
  // derivation step regenerates a tree at the finest dyad's detail from the rules.
  int axiom = options.axiom_level.value_or(levels - 2);
  if (!options.axiom_level) {
    // Fall back to a finer dyad when the default one has no vector (tiny scans).
    while (axiom + 1 < levels && vectors[std::size_t(axiom)].empty()) ++axiom;
    while (axiom > 0 && vectors[std::size_t(axiom)].empty()) --axiom;
  }
  if (r.dyad_vectors == 0) {
    throw std::invalid_argument(
        "no dyad has two significant coefficients, so there is no spanning tree to infer "
        "L-rules from (" +
        std::to_string(r.occupied_voxels) + " occupied voxel(s) at " + std::to_string(grid.n) +
        "^3; a larger or denser scan, or a finer --grid, is needed)");
  }
  if (vectors[std::size_t(axiom)].empty()) {
    throw std::invalid_argument("dyad " + std::to_string(axiom) +
                                " has no spanning-tree vector to use as the axiom; choose "
                                "another --axiom-level");
  }
  r.axiom_level = axiom;

  // III-E joined into one tree per dyad, refining the coarser one from the scan's base
  // (tree_hierarchy.h), at the centroids of the points.
  HierarchyOptions ho;
  ho.offset = options.offset;
  const std::vector<LevelTree> hierarchy = tree_hierarchy(trees, cloud, grid, ho);
  LsystemTextOptions lo;
  lo.name = options.name;
  lo.seed = options.seed;
  lo.axiom_level = axiom;
  lo.offset = to_string(options.offset);
  const LsystemText ls = lsystem_text(hierarchy, lo);
  r.l_rules = ls.rules;
  r.productions = ls.productions;
  r.axiom_vectors = ls.axiom_vectors;
  clock.done("l-rules");

  std::string text;
  text += "// Inferred by `ramus infer --method wavelet` (Friedman & Stamos 2013, section III)";
  text += options.source.empty() ? std::string(".\n") : " from " + options.source + ".\n";
  text += "// Grid " + std::to_string(grid.n) + "^3 (voxel " + num(grid.voxel_size, 4) + " m), " +
          std::to_string(r.occupied_voxels) +
          " occupied voxels; aligned frame: root "
          "at the origin, z up, +y away from the scanner.\n";
  text += "// Compression (IV-A): lossless " + num(100 * r.compression.lossless_ratio, 3) +
          "%, lossy " + num(100 * r.compression.lossy_ratio, 3) + "% (gamma " + num(options.gamma) +
          "), lossy IoU " + num(r.compression.lossy_iou, 3) + ".\n\n";
  text += ls.params + "\n";
  text +=
      "// One spanning-tree vector: turtle turns a (about the vertical) and e (down from it),\n"
      "// length l and width w in metres, s the cell edge of its dyad.\n";
  text += "module V(a, e, l, s, w);\n\n";
  // The voxels block is written in the formatter's layout already and is spliced in after the
  // layout pass: its rules, hundreds of lines, need not be parsed once more.
  const std::string voxels = voxels_block(options, vg, r.voxel_rules) + "\n";
  const std::string lsystem_mark = "// L-system (III-F, III-G)";
  text += lsystem_mark +
          ": each production replaces a vector of dyad j by the\n"
          "// vectors of dyad j+1 that refine it (tree_hierarchy.h; offset " +
          std::string(to_string(options.offset)) +
          "), drawn from its start\n"
          "// and ending where it ends, so the regrown tree is one piece rooted at the base.\n";
  text += ls.lsystem;
  r.ramus_text = canonical_layout(text);
  const std::size_t at = r.ramus_text.find("\n" + lsystem_mark);
  if (at == std::string::npos || r.ramus_text.size() < 2 ||
      r.ramus_text.compare(r.ramus_text.size() - 2, 2, "}\n") != 0) {
    throw std::logic_error("the inferred grammar lost its L-system");
  }
  // The productions before the block's closing brace, then the voxels block before the block.
  r.ramus_text.insert(r.ramus_text.size() - 2, ls.productions_text);
  r.ramus_text.insert(at + 1, voxels);
  clock.done("emit");
  r.total_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  if (!cloud.alignment.warning.empty()) r.warnings.push_back(cloud.alignment.warning);
  return r;
}

}  // namespace ramus::wavelet
