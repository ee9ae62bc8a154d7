// The trees a tile keeps (docs/scale.md): a tile reconstructs every tree of its buffered box, but
// keeps only those whose base (the root) lies in its core, so that the cores, which partition the
// plot, give every tree exactly once. A kept tree that reaches the buffered box's edge was
// probably cut there: its crown is wider than the buffer allows for.
#pragma once

#include <vector>

#include "core/skeleton.h"

namespace ramus::forest {

// [x0, x1) x [y0, y1) in the ground plane.
struct GroundBox {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool contains(double x, double y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
};

struct CoreTrees {
  std::vector<Skeleton> kept;         // in the order given
  std::vector<std::size_t> touching;  // indices into `kept`: within `margin` of the buffered edge
};

// `margin` is how close to the buffered box's edge a node counts as touching it (a voxel or two).
// An edge of the buffered box beyond which `data` holds no point is not a cut: pass the bounds of
// the tile's points as `data`.
CoreTrees keep_core_trees(const std::vector<Skeleton>& trees, const GroundBox& core,
                          const GroundBox& buffered, const GroundBox& data, double margin);

}  // namespace ramus::forest
