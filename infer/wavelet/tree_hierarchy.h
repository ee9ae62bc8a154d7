// One tree per dyad, each a refinement of the coarser one, all rooted at the scan's base.
//
// Friedman & Stamos 2013 (III-E) compute an independent spanning tree in every dyad and (III-F,
// Eq. 1-3) relate a vector of dyad j to the vectors of dyad j + 1 whose ends fall in its box.
// Regrown that way the tree falls apart: the boxes of neighbouring vectors overlap or leave
// gaps, each box holds several unconnected pieces of the finer tree, a dyad's tree starts at
// its lowest significant coefficient instead of the ground, and a straight trunk, having no
// diagonal detail, is missing from every dyad. Here the trees are built from the coarsest dyad
// down so that every finer tree refines the coarser one:
//
// - Level "-1" is the base: the foot of the trunk, at the height of the scan's lowest point
//   (III-A's root, the origin), under the densest column of the lowest 5 % of the points; and
//   the trunk traced up from it through the points (trace_trunk in the .cpp), whose nodes stay
//   in every finer tree as the entries of the cells they own.
// - Dyad j's significant cells (III-E's nodes; positions: cell_centroids.h) each belong to one
//   node of tree j - 1, its *owner*: the node whose cell holds them (the box of Eq. 2-3 for a
//   single cell, in the scaled or the exact reading), or the nearest node when that cell is not
//   significant (the data leave a gap there).
// - A node of tree j - 1 that owns no cell of dyad j is kept in tree j at its position: the
//   coarser dyad saw wood there that the finer one does not resolve (a straight trunk).
// - The cells a node owns are joined by their Euclidean minimum spanning tree (III-E), entered
//   at the member nearest to the entry of the owner's parent, and linked to it by that edge:
//   the shortest connection to the coarser level's tree. An edge longer than one and a half
//   cells runs through the centroids of the occupied cells along it (a straight trunk has
//   points but no diagonal detail); only where the data leave a gap is it a straight edge.
//
// So tree j is one tree rooted at the base, and the edge p -> u of tree j - 1 is refined by the
// link into u's cells and u's cells' own tree: the successors of one L-rule (III-F), every
// vector of dyad j in exactly one rule.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/skeleton.h"
#include "core/vec3.h"
#include "infer/wavelet/alignment.h"
#include "infer/wavelet/dyad_tree.h"
#include "infer/wavelet/l_rules.h"
#include "infer/wavelet/voxel_grid.h"

namespace ramus::wavelet {

struct HierarchyNode {
  Vec3 position;                     // aligned frame, metres
  std::uint32_t parent = kNoParent;  // in the same level's tree; kNoParent for the base
  std::uint32_t owner = kNoParent;   // the node of the next coarser tree it refines
  std::uint32_t leaves = 0;          // leaves in its subtree (Da Vinci weight, III-E)
  double width = 0;                  // of the segment from its parent, metres
  bool inherited = false;            // kept from the coarser tree (no significant cell here)
  bool trunk = false;                // on the trunk traced from the foot (kept in every dyad)
};

struct LevelTree {
  int level = 0;                     // the dyad
  double cell = 0;                   // edge of one cell of the dyad, metres
  std::vector<HierarchyNode> nodes;  // node 0 is the base
  // entry[u] for each node u of the coarser tree: the node of this tree where u's cells start
  // (their spanning tree's root). The chain from entry[parent of u] to it is u's link.
  std::vector<std::uint32_t> entry;
  std::vector<std::vector<std::uint32_t>> children;  // per node, ascending
  // Each node's cell (local index in the dyad); {-1, -1, -1} for the base and inherited nodes.
  std::vector<std::array<int, 3>> cell_of;
};

struct HierarchyOptions {
  LRuleOffset offset = LRuleOffset::scaled;
};

// Trees for dyads 0 .. L-1 (index = dyad), built coarse to fine from the dyad trees of III-E.
std::vector<LevelTree> tree_hierarchy(const std::vector<DyadTree>& dyads, const AlignedCloud& cloud,
                                      const VoxelGrid& grid, const HierarchyOptions& options = {});

}  // namespace ramus::wavelet
