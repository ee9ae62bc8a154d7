// Preparing a Skeleton for meshing: checking it, choosing radii (skeleton or pipe model) and
// splitting it into branch chains, each swept as one generalized cylinder.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/tree_mesh.h"

namespace ramus::mesh {

inline constexpr std::uint32_t kNoChain = 0xffffffffu;

// A chain: nodes[0] is where the tube starts (the root, or for a lateral the parent node on the
// parent's axis, so the lateral begins inside the parent tube and the fork has no gap); each
// following node ends one segment. A chain continues through a node to its child of lowest order,
// then largest radius, then lowest index; the other children start new chains.
struct Chain {
  std::vector<std::uint32_t> nodes;
  std::uint32_t parent_chain = kNoChain;
  std::uint16_t order = 0;
};

struct PreparedSkeleton {
  std::vector<double> radius;                // per node, clamped, after the pipe model if asked
  std::vector<Chain> chains;                 // parents before children
  std::vector<std::uint32_t> chain_of_node;  // the chain whose segment ends at the node
  double max_radius = 0.0;
  double min_radius = 0.0;  // the floor radii were clamped to
  double extent = 0.0;      // diagonal of the node bounds
  Vec3 lo, hi;              // node bounds
};

// Throws MeshError on non-finite values or broken parent links; fills `report`.
PreparedSkeleton prepare_skeleton(const Skeleton& skeleton, const MeshOptions& options,
                                  MeshReport& report);

}  // namespace ramus::mesh
