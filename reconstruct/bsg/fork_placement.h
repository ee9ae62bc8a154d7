// Forks of thick stems moved from the crotch to where the axes meet. On samples of the bark,
// the BSG's shortest paths (Livny et al. 2010, 4.1) part where the bark of two stems parts: at
// the crotch, about r / sin(half the branching angle) beyond the point where the axes meet (60 cm
// along a 20 cm limb at 40 degrees). Once the centre lines have put the stems' nodes on their
// axes, a side branch is re-attached where its own axis, continued backwards across the crotch,
// meets the axis of the stem it leaves (docs/reconstruction.md, Centre lines).
#pragma once

#include <cstdint>
#include <vector>

#include "reconstruct/bsg/bsg.h"

namespace ramus::bsg {

// For every side branch (not the heaviest child) of a fork whose first nodes are fitted, the
// point of the stem around the fork (the fork's ancestors and its heaviest chain, up to a few
// stem radii away, edges with both ends fitted) nearest to the branch's axis continued backwards;
// when the two axes pass within half the stem's radius there and that point is not the fork,
// the branch hangs from it (a new node splits the stem's edge unless a node is within two
// spacings). A fork left with one child and no fit moves onto the segment between its parent
// and child. `fitted` is extended for new nodes (fitted: they lie on fitted edges). Keeps
// parents before children. Returns the number of branches moved.
std::size_t place_forks(Bsg& bsg, std::vector<std::uint8_t>& fitted, double spacing);

}  // namespace ramus::bsg
