// L-system rules from the wavelet progression (Friedman & Stamos 2013, III-F, Eq. 1-3 in 3D).
//
// "Given a vector from points alpha to beta in the spanning tree of the j-th dyad we associate the
// vectors whose start or end points fall within the rectangle bounded by points r1 and r2", with
//   d_offset = 2^(j+1) - 2^j                                            (1)
//   r1 = (min(alpha_x, beta_x) + d_offset, min(alpha_y, beta_y) + d_offset)   (2)
//   r2 = (max(alpha_x, beta_x) + d_offset, max(alpha_y, beta_y) + d_offset)   (3)
// in the coordinates of the transform array, where dyad j is the cube [2^j, 2^(j+1))^3. Here the
// same bounds are taken along z as well, and the box is closed (a point on its face is inside).
//
// Two readings of the offset:
// - LRuleOffset::exact, Eq. 1-3 as written: the box is the vector's bounding box translated by
//   2^j. That maps dyad j onto the corner octant [2^(j+1), 2^(j+1) + 2^j)^3 of dyad j + 1: a
//   translation, not a change of scale, so only vectors near the low corner of the finer dyad
//   are ever reached and most of dyad j + 1 is never a successor.
// - LRuleOffset::scaled (the default): the box of the *same region of space* in dyad j + 1. Cell c
//   of dyad j (absolute index) covers the cells 2c and 2c + 1 of dyad j + 1 along each axis
//   (local index c - 2^j covers 2(c - 2^j) and 2(c - 2^j) + 1, absolute 2c and 2c + 1), so
//   r1 = 2 min(alpha, beta) and r2 = 2 max(alpha, beta) + 1. In 1D at the corner cell c = 2^j
//   this agrees with Eq. 2 (2c = c + d_offset); it is the reading under which the arrows of the
//   paper's Figure 8 join the same branch in neighbouring dyads, and the one whose rules cover
//   every vector of dyad j + 1.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "infer/wavelet/dyad_tree.h"

namespace ramus::wavelet {

enum class LRuleOffset { exact, scaled };

// Parses "exact" / "scaled"; throws std::invalid_argument naming the bad word.
LRuleOffset parse_l_rule_offset(const std::string& word);
const char* to_string(LRuleOffset offset);

// One edge of a dyad's spanning tree, directed away from the root: alpha = parent, beta = child.
struct DyadVector {
  std::uint32_t from = 0, to = 0;     // node indices in the DyadTree
  std::array<int, 3> start{}, end{};  // their absolute array indices (alpha, beta)
};

// The tree's edges, ordered by child node index.
std::vector<DyadVector> dyad_vectors(const DyadTree& tree);

// An axis-aligned closed box of array indices (r1, r2 of Eq. 2-3).
struct SuccessorBox {
  std::array<std::int64_t, 3> r1{}, r2{};
  bool contains(const std::array<int, 3>& p) const {
    for (int k = 0; k < 3; ++k) {
      if (p[k] < r1[k] || p[k] > r2[k]) return false;
    }
    return true;
  }
};

// Eq. 1: 2^(j+1) - 2^j.
std::int64_t dyad_offset(int level);
// Eq. 2-3 for a vector of dyad `level` (exact), or its scaled reading.
SuccessorBox successor_box(const DyadVector& v, int level, LRuleOffset offset);

// An L-rule: one vector of dyad `level` and the vectors of dyad `level + 1` that start or end in
// its box.
struct LRule {
  int level = 0;
  std::uint32_t predecessor = 0;          // index into the coarse dyad's vectors
  std::vector<std::uint32_t> successors;  // indices into the fine dyad's vectors, ascending
};

// The L-rules from dyad j (`coarse`) to dyad j + 1 (`fine`), one per coarse vector that has at
// least one successor, in coarse vector order.
std::vector<LRule> l_rules(int level, const std::vector<DyadVector>& coarse,
                           const std::vector<DyadVector>& fine, LRuleOffset offset);

}  // namespace ramus::wavelet
