// The multi-root Dijkstra of 4.1: all roots start at distance 0 (the paper's temporary zero-weight
// links between roots), so one run yields a forest with one tree per root -- the segmentation.
#pragma once

#include <cstdint>
#include <vector>

#include "reconstruct/bsg/bsg.h"

namespace ramus::bsg {

Forest shortest_path_forest(const Graph& graph, const std::vector<std::uint32_t>& roots);

// Fraction of reached vertices whose parent differs between two forests of the same graph.
double forest_change(const Forest& a, const Forest& b);

// The tree `t` of a forest as a Bsg (parents before children), positions from the graph.
Bsg extract_tree(const Graph& graph, const Forest& forest, std::uint32_t t,
                 const std::vector<std::uint32_t>& roots);

}  // namespace ramus::bsg
