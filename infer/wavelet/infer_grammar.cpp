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

// Numbers in the grammar: 6 significant digits are far below a voxel and keep the file small.
std::string num(double v, int digits = 6) {
  if (!std::isfinite(v)) throw std::logic_error("non-finite number in an inferred grammar");
  if (v == 0) return "0";  // also turns -0 into 0
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

// Geometry of one vector of dyad `level`, in the aligned frame (metres).
struct VectorGeometry {
  Vec3 heading{0, 0, 1};
  double cells = 0;   // length in cells of its dyad (the rule-space length)
  double length = 0;  // metres
  double cell = 0;    // edge of one cell of its dyad, metres
  double width = 0;   // Da Vinci: 2 * leaf_radius * sqrt(leaves), metres (III-E)
};

class GrammarWriter {
 public:
  GrammarWriter(const std::vector<DyadTree>& trees, const VoxelGrid& grid,
                const DyadTreeOptions& tree_options)
      : trees_(trees), grid_(grid), tree_options_(tree_options) {}

  VectorGeometry geometry(int level, const DyadVector& v) const {
    VectorGeometry g;
    const DyadTree& t = trees_[std::size_t(level)];
    g.cell = grid_.voxel_size * double(grid_.n) / double(std::size_t(1) << level);
    Vec3 d(double(v.end[0] - v.start[0]), double(v.end[1] - v.start[1]),
           double(v.end[2] - v.start[2]));
    g.cells = length(d);
    if (g.cells > 0) g.heading = d / g.cells;
    g.length = g.cells * g.cell;
    // Da Vinci's rule on areas, capped at the cell: a coefficient describes one cell, and the
    // many short twigs a noisy dyad tree ends in would otherwise make trunks metres thick.
    g.width =
        std::min(2 * tree_options_.leaf_radius * std::sqrt(double(t.leaves[v.to])), 1.0) * g.cell;
    return g;
  }

  // V(hx, hy, hz, l, s, w) with absolute values (the axiom).
  std::string module(const VectorGeometry& g) const {
    return "V(" + num(g.heading.x) + ", " + num(g.heading.y) + ", " + num(g.heading.z) + ", " +
           num(g.length) + ", " + num(g.cell) + ", " + num(g.width) + ")";
  }
  // A successor relative to its predecessor: lengths and widths scale with the predecessor's, so
  // a rule applies at any scale (the rule-space length is in cells of the vector's own dyad).
  std::string successor(const VectorGeometry& pred, const VectorGeometry& g) const {
    return "V(" + num(g.heading.x) + ", " + num(g.heading.y) + ", " + num(g.heading.z) + ", l * " +
           num(g.length / pred.length) + ", s * 0.5, w * " + num(g.width / pred.width) + ")";
  }
  std::string key(const VectorGeometry& g) const {
    return "@ (" + num(g.heading.x, 4) + ", " + num(g.heading.y, 4) + ", " + num(g.heading.z, 4) +
           ", " + num(g.cells, 4) + ")";
  }

  // Centre of cell `c` (absolute array index) of dyad `level`, aligned frame (metres): the
  // position to_skeleton gives the node of that cell.
  Vec3 position(int level, const std::array<int, 3>& c) const {
    const DyadTree& t = trees_[std::size_t(level)];
    const double cell = grid_.voxel_size * double(grid_.n) / double(std::size_t(1) << level);
    Vec3 local;
    for (int k = 0; k < 3; ++k) local[k] = double(c[k] - int(t.block.offset[k])) + 0.5;
    return grid_.origin + local * cell;
  }

  // A bracketed tree of `vectors` (indices into `all`, vectors of dyad `level`): every vector is
  // followed by the vectors that start at its end; the continuation with most leaves comes last
  // and unbracketed, so the turtle ends at the tip of the main axis. `text(i)` spells vector i.
  // With `bracket_roots`, every root of the forest (a vector not starting at another one's end)
  // is bracketed too and preceded by `root_prefix(i)` (when not empty), so that the turtle is
  // back where it started once the forest is drawn.
  template <class Text, class Prefix>
  std::string tree_string(int level, const std::vector<DyadVector>& all,
                          const std::vector<std::uint32_t>& vectors, Text&& text,
                          bool bracket_roots, Prefix&& root_prefix) const {
    const DyadTree& t = trees_[std::size_t(level)];
    // Children of each chosen vector (by its end node), and the roots of the chosen forest.
    std::unordered_set<std::uint32_t> chosen_ends;
    for (std::uint32_t i : vectors) chosen_ends.insert(all[i].to);
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> starting_at;
    std::vector<std::uint32_t> roots;
    for (std::uint32_t i : vectors) {
      starting_at[all[i].from].push_back(i);
      if (!chosen_ends.count(all[i].from)) roots.push_back(i);
    }
    auto ordered = [&](std::vector<std::uint32_t> list) {
      // Branches by index, the continuation (most leaves, then the smallest index) last.
      std::sort(list.begin(), list.end());
      auto main = std::max_element(list.begin(), list.end(), [&](std::uint32_t a, std::uint32_t b) {
        return t.leaves[all[a].to] < t.leaves[all[b].to];
      });
      std::rotate(main, main + 1, list.end());
      return list;
    };
    // Iterative depth-first writing: chains in the finest dyads are thousands of vectors long.
    struct Item {
      std::uint32_t vector;
      int what;  // 0: the vector and its subtree, 1: "[", 2: "]", 3: the root prefix
    };
    std::vector<Item> stack;
    auto push_list = [&](const std::vector<std::uint32_t>& list, bool all_bracketed) {
      for (std::size_t k = list.size(); k-- > 0;) {
        const bool branch = all_bracketed || k + 1 < list.size();
        if (branch) stack.push_back({0, 2});
        stack.push_back({list[k], 0});
        if (all_bracketed) stack.push_back({list[k], 3});
        if (branch) stack.push_back({0, 1});
      }
    };
    std::string out;
    push_list(ordered(roots), bracket_roots);
    while (!stack.empty()) {
      const Item item = stack.back();
      stack.pop_back();
      if (item.what == 3) {
        const std::string prefix = root_prefix(item.vector);
        if (!prefix.empty()) out += ' ' + prefix;
        continue;
      }
      if (!out.empty() && item.what != 2) out += ' ';
      if (item.what == 1) {
        out += '[';
      } else if (item.what == 2) {
        out += " ]";
      } else {
        out += text(item.vector);
        auto it = starting_at.find(all[item.vector].to);
        if (it != starting_at.end()) push_list(ordered(it->second), false);
      }
    }
    return out;
  }

 private:
  const std::vector<DyadTree>& trees_;
  const VoxelGrid& grid_;
  const DyadTreeOptions& tree_options_;
};

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

WaveletInference infer_wavelet_grammar(const AlignedCloud& cloud,
                                       const WaveletInferOptions& options) {
  const Clock::time_point t0 = Clock::now();
  const int levels = checked_levels(options);
  if (cloud.points.empty()) throw std::invalid_argument("the scan has no points");
  WaveletInference r;
  StageClock clock(r.timings);
  r.points = cloud.points.size();

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

  // III-F: the L-rules of every pair of neighbouring dyads.
  std::vector<LRule> rules;
  for (int j = 0; j + 1 < levels; ++j) {
    std::vector<LRule> pair =
        l_rules(j, vectors[std::size_t(j)], vectors[std::size_t(j + 1)], options.offset);
    rules.insert(rules.end(), pair.begin(), pair.end());
  }
  r.l_rules = rules.size();
  clock.done("l-rules");

  // III-G: the axiom is one dyad's tree; by default the second finest, so that one derivation
  // step regenerates a tree at the finest dyad's detail from the rules.
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
  r.axiom_vectors = vectors[std::size_t(axiom)].size();

  GrammarWriter w(trees, grid, to);
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
  text += "module V(x, y, z, l, s, w);\n";
  text += "module Trunk(x, y, z, l, w);\n";
  text += "module Shift(x, y, z, l);\n\n";
  text += voxels_block(options, vg, r.voxel_rules) + "\n";

  text +=
      "// L-system (III-F, III-G). V(x, y, z, l, s, w) is one spanning-tree vector: unit\n"
      "// heading (x, y, z) in the aligned frame, length l and width w in metres, s the cell\n"
      "// edge of its dyad. A production maps a vector of dyad j to the vectors of dyad j+1\n"
      "// in its box (Eq. 1-3, offset " +
      std::string(to_string(options.offset)) +
      "); a vector picks the production whose key\n"
      "// (heading, length in cells) is nearest. Each group of successors is drawn in\n"
      "// brackets from its own start (Shift: a move relative to the predecessor's start),\n"
      "// then the turtle moves along the predecessor to its end, where the next vector\n"
      "// starts. The axiom is dyad " +
      std::to_string(axiom) +
      "; its Trunk runs from the scan's lowest point to the\n"
      "// dyad's root (a straight trunk has no diagonal detail, so no vector of its own).\n";
  text += "lsystem " + options.name + " {\n";
  text += "  derive 1;\n";
  text += "  seed " + std::to_string(options.seed) + ";\n";
  text += "  select nearest(x, y, z, l / s);\n";
  // A straight move or segment (unit direction, length) as Shift / Trunk arguments; empty when
  // the displacement is below a thousandth of a cell (nothing to draw or move).
  auto direction = [](const Vec3& d, double scale, const std::string& length_prefix) {
    const double len = length(d);
    const Vec3 u = d / len;
    return num(u.x) + ", " + num(u.y) + ", " + num(u.z) + ", " + length_prefix + num(len / scale);
  };
  bool has_trunk = false;
  {
    const std::vector<DyadVector>& av = vectors[std::size_t(axiom)];
    std::vector<std::uint32_t> all(av.size());
    for (std::uint32_t i = 0; i < all.size(); ++i) all[i] = i;
    // The turtle starts at the origin, the scan's lowest point (III-A); the axiom dyad's tree
    // starts at its root, its lowest significant coefficient.
    const DyadTree& at = trees[std::size_t(axiom)];
    const VectorGeometry cell = w.geometry(axiom, av.front());
    const Vec3 root = w.position(axiom, at.cells[at.root]);
    std::string trunk;
    if (length(root) > 1e-3 * cell.cell) {
      double width = 0;
      for (const DyadVector& v : av) {
        if (v.from == at.root) width = std::max(width, w.geometry(axiom, v).width);
      }
      trunk = "Trunk(" + direction(root, 1.0, "") + ", " + num(width) + ") ";
      has_trunk = true;
    }
    text += "  axiom " + trunk +
            w.tree_string(
                axiom, av, all, [&](std::uint32_t i) { return w.module(w.geometry(axiom, av[i])); },
                false, [](std::uint32_t) { return std::string(); }) +
            ";\n";
  }
  // The turtle keeps its initial frame between vectors: each V turns to its absolute heading
  // (roll about the initial heading z, then pitch), draws, and turns back in reverse order.
  // Trunk draws and Shift moves the same way.
  std::string productions;
  const std::string turn = "/(atan2(x, y)) &(acos(clamp(z, -1, 1)))";
  const std::string back = "^(acos(clamp(z, -1, 1))) \\(atan2(x, y))";
  text += "  interpret V(x, y, z, l, s, w) -> !(w) " + turn + " F(l) " + back + ";\n";
  std::unordered_set<std::string> keys;
  for (const LRule& rule : rules) {
    const std::vector<DyadVector>& coarse = vectors[std::size_t(rule.level)];
    const std::vector<DyadVector>& fine = vectors[std::size_t(rule.level + 1)];
    const VectorGeometry pred = w.geometry(rule.level, coarse[rule.predecessor]);
    if (!(pred.length > 0)) continue;
    std::string key = w.key(pred);
    if (!keys.insert(key).second) continue;  // an equal key would never be chosen (ties: first)
    const int fl = rule.level + 1;
    // Eq. 1-3 find successors anywhere in the predecessor's box: each group starts where its
    // first vector starts, relative to the predecessor's start, in units of its length.
    const Vec3 pred_start = w.position(rule.level, coarse[rule.predecessor].start);
    auto offset = [&](std::uint32_t i) {
      const Vec3 d = w.position(fl, fine[i].start) - pred_start;
      if (length(d) <= 1e-3 * pred.cell) return std::string();
      return "Shift(" + direction(d, pred.length, "l * ") + ")";
    };
    productions += "  V(x, y, z, l, s, w) " + key + " -> " +
                   w.tree_string(
                       fl, fine, rule.successors,
                       [&](std::uint32_t i) { return w.successor(pred, w.geometry(fl, fine[i])); },
                       true, offset) +
                   " Shift(x, y, z, l);\n";
    ++r.productions;
  }
  // Trunk and Shift are interpreted only when they occur (an unused interpretation is a warning).
  if (has_trunk)
    text += "  interpret Trunk(x, y, z, l, w) -> !(w) " + turn + " F(l) " + back + ";\n";
  if (r.productions > 0)
    text += "  interpret Shift(x, y, z, l) -> " + turn + " f(l) " + back + ";\n";
  text += productions;
  text += "}\n";
  r.ramus_text = canonical_layout(text);
  clock.done("emit");
  r.total_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  if (!cloud.alignment.warning.empty()) r.warnings.push_back(cloud.alignment.warning);
  return r;
}

}  // namespace ramus::wavelet
