// Inferring one .ramus grammar from a scan with the wavelet method of Friedman & Stamos 2013
// (III-A to III-G): alignment and voxelization, the 3D Haar transform, the voxel grammar of the
// finest dyads (a `voxels` block), the spanning trees of the dyads joined into one tree per dyad
// that refines the coarser one from the trunk's foot (tree_hierarchy.h, beyond the paper: the
// literal reading regrows a tree in pieces), the L-rules that map each vector of tree j to the
// vectors of tree j + 1 refining it (III-F), and the rule space of III-G (`select nearest` over
// heading and length; lsystem_text.h). The axiom is the tree of one dyad.
//
// The result is the text of an ordinary .ramus file that `ramus check` and `ramus build` accept.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "infer/wavelet/alignment.h"
#include "infer/wavelet/compression.h"
#include "infer/wavelet/l_rules.h"
#include "infer/wavelet/quantizer.h"
#include "infer/wavelet/voxelize.h"

namespace ramus::wavelet {

struct WaveletInferOptions {
  int grid = 64;                   // voxel grid side, a power of two in [4, 256]
  std::optional<int> axiom_level;  // the dyad whose tree is the axiom; default: see infer_grammar
  LRuleOffset offset = LRuleOffset::scaled;  // l_rules.h explains the default
  VoxelValues values = VoxelValues::occupancy;
  double mst_threshold = 0.3;  // III-E, relative to each dyad's largest |coefficient|
  double gamma = 0.2;          // IV-A lossy threshold, for the compression figures
  int classes = kDefaultClasses;
  std::uint64_t seed = 1;     // the grammar's `seed` setting and the voxel block's seed
  std::string name = "scan";  // block names: lsystem <name>, voxels <name>_voxels
  std::string source;         // shown in the header comment (e.g. the scan's file name)
};

struct StageTiming {
  std::string stage;  // "voxelize", "haar", "compression", "voxel grammar", "spanning trees",
                      // "l-rules", "emit"
  double seconds = 0.0;
};

struct WaveletInference {
  std::string ramus_text;  // the whole grammar file

  // Figures the CLI prints.
  std::size_t points = 0;
  std::size_t grid_side = 0;
  std::size_t occupied_voxels = 0;
  CompressionStats compression;  // of the standard decomposition (Table I)
  std::size_t voxel_rules = 0;   // rules in the voxels block
  std::size_t dyad_vectors = 0;  // MST edges over all dyads
  std::size_t l_rules = 0;       // L-rules found (one per predecessor vector with successors)
  std::size_t productions = 0;   // productions written (distinct keys after merging)
  int axiom_level = 0;
  std::size_t axiom_vectors = 0;
  std::vector<std::size_t> vectors_per_dyad;  // index = dyad level
  std::vector<StageTiming> timings;
  double total_seconds = 0.0;
  std::vector<std::string> warnings;  // for the caller to show
};

// Throws std::invalid_argument naming the option (as `ramus infer` spells it) when an option is
// out of range: grid not a power of two in [4, 256], axiom level outside [0, log2(grid)).
void validate_options(const WaveletInferOptions& options);

// Runs the whole inference on an aligned cloud (align_cloud). Throws std::invalid_argument with a
// user-readable message for bad options (grid not a power of two or outside [4, 256], an axiom
// level outside the pyramid) or an unusable cloud (empty, fewer points than needed for any
// spanning tree).
WaveletInference infer_wavelet_grammar(const AlignedCloud& cloud,
                                       const WaveletInferOptions& options = {});

}  // namespace ramus::wavelet
