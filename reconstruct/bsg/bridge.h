// Joining the graph components that occlusion separates (Livny et al. 2010, 4.1: gaps between
// components are bridged before Dijkstra), preferring links that continue a fragment's own branch.
#pragma once

#include <cstdint>
#include <vector>

#include "reconstruct/bsg/bsg.h"

namespace ramus::bsg {

struct BridgeParams {
  double max_gap = 0;  // no bridge is longer, but for a hidden limb's (below)
  // A component whose bounding box has a diagonal of at least `hidden_limb_length` may bridge up
  // to `hidden_limb_gap`: a limb that leaves a stem on its far side from the scanner is seen
  // only from where it clears the stem, more than the stem's diameter from anything reached.
  // 0 turns the longer reach off.
  double hidden_limb_length = 0;
  double hidden_limb_gap = 0;
  // A fragment is elongated (a piece of one branch) when the largest eigenvalue of its vertices'
  // covariance is at least `linearity` times the second and it has `min_vertices` vertices.
  double linearity = 4.0;
  std::size_t min_vertices = 6;
  double cone_degrees = 25.0;  // half-angle of the cones along an elongated fragment's axis
  // A link of an elongated fragment that is not along its axis ranks as if this many times
  // longer: the nearest bark is often a neighbouring branch's, the continuation lies ahead.
  double off_axis_penalty = 3.0;
};

// Bridges gaps left by occlusion: repeatedly joins each component not reachable from a root to
// the reachable part, smallest (ranked) gaps first, as long as the gap is at most max_gap (or
// hidden_limb_gap for a component at least hidden_limb_length across). An
// elongated component links from one of its two ends to the nearest reachable vertex in the cone
// around its axis ahead of that end, unless a link outside the cones is `off_axis_penalty` times
// shorter; other components link through their closest pair. Returns the number of bridges.
std::size_t bridge_gaps(Graph& graph, const std::vector<std::uint32_t>& roots,
                        const BridgeParams& params);
std::size_t bridge_gaps(Graph& graph, const std::vector<std::uint32_t>& roots, double max_gap);

}  // namespace ramus::bsg
