// Chains that the centre lines put on one axis, joined into one. On a thick stem scanned from
// all sides the BSG's shortest paths run up the bark in several parallel lines (Livny et al.
// 2010, 4.1), one for each branch the stem carries: each path goes up its own side of the stem
// to where its branch leaves. The centre lines (centre_line.h) move every fitted node onto the
// stem's axis, so the paths end up on top of each other: the 14 m harness tree of seed 2 from
// three stations had three chains up its trunk from the root (four in places), 52 of its 136 m
// of skeleton within 3 cm of another chain, and 1.41 x the truth's length.
// drop_branches_inside_stems removes a copy only when it is a leaf chain; these go on into their
// branches.
// docs/reconstruction.md, "Centre lines", step 11.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "reconstruct/bsg/bsg.h"

namespace ramus::bsg {

struct CoincidentChainParams {
  double spacing = 0;  // the voxel: the graph does not tell apart two chains closer than it
  // Coincident: within max(spacings x spacing, radius_share x the larger radius) and running
  // within acos(cos_parallel) of each other.
  double spacings = 1.0;
  double radius_share = 0.25;
  double cos_parallel = 0.866;
};

// In parent-first order, every node is joined to the edge of another chain that runs within the
// tolerance above, the same way (not against it), off the node's own line of descent (not
// between two of its ancestors, not below it): the node moves onto that edge and splits it,
// keeping its children and taking the edge's radius there. So a copy of a stem is zipped into
// the first node by node, and where it leaves the stem its branch leaves from the stem's one
// chain; a chain that runs within the tolerance of no other is unchanged. What a copy ran along
// before it came within the tolerance (down behind its fork and back up, or beside the stem
// farther out) is a leaf chain then, and goes by drop_chains_inside_edges (centre_line.h) with
// every other edge as a container. Keeps parents before children (depth first). Returns the
// number of nodes joined.
std::size_t join_coincident_chains(Bsg& bsg, const CoincidentChainParams& params);

}  // namespace ramus::bsg
