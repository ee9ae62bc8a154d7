// The `lsystem` block of an inferred wavelet grammar (Friedman & Stamos 2013, III-F and III-G),
// written from the coarse-to-fine trees of tree_hierarchy.h.
//
// - `V(a, e, l, s, w)` is one vector: the turtle turns that give its heading (roll a about the
//   vertical, then pitch down e from it, degrees), length l and width w in metres, s the cell
//   edge of its dyad. Headings and lengths are the measured ones, between the centroids of the
//   points of the cells (cell_centroids.h).
// - One production per vector p -> u of tree j - 1 (every level pair, finest first): its
//   successors are the vectors of tree j that refine it, the link into u's cells and their own
//   tree, all branches bracketed, so the turtle ends where the next vector starts and
//   everything is drawn with the pen down: the regrown tree is one piece.
// - III-G's rule space: `select nearest(heading, l / s)` with a key `@ (hx, hy, hz, cells)` on
//   each production; keys equal at 4 digits to an earlier one are dropped (never chosen).
// - The quantities a reader may want to change are `param`s the text uses by name: `cell` (the
//   axiom's lengths and widths are multiples of it), `branch_tilt` (laterals' angle from the
//   vertical) and `width_ratio` (laterals' width relative to the vector they refine).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "infer/wavelet/tree_hierarchy.h"

namespace ramus::wavelet {

struct LsystemTextOptions {
  std::string name = "scan";
  std::uint64_t seed = 1;
  int axiom_level = 0;  // index into the trees
  std::string offset = "scaled";
};

struct LsystemText {
  std::string params;   // the `param` lines, with their comments
  std::string lsystem;  // the block without its rewriting productions
  // The rewriting productions, each after its comment, already in `ramus fmt` layout
  // (wrap_modules, grammar/format.h): they go before the block's closing brace after the layout
  // pass.
  std::string productions_text;
  std::size_t rules = 0;        // vectors with successors (L-rules)
  std::size_t productions = 0;  // written (distinct keys)
  std::size_t axiom_vectors = 0;
};

LsystemText lsystem_text(const std::vector<LevelTree>& trees, const LsystemTextOptions& options);

}  // namespace ramus::wavelet
