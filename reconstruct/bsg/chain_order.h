// Chains put in order along their axes. On a thick stem the BSG's shortest paths wind over the
// bark, up and down around it (Livny et al. 2010, 4.1); the centre lines (centre_line.h) move
// each node onto the axis at its own height, so a chain between two forks can run up and down
// the axis (thick_oak from three stations: 251 of 4,228 edges of branches of 5 cm or more step
// back along their chain), and a mesh of it pinches at every turn. Dropping the nodes that step
// back straightened the stems but lost the nodes' fits (a 20-40 cm class from 0.05 to 0.13 r);
// here the nodes stay and only their order changes: Livny 4.2 takes branches to be smooth, and
// a smooth chain visits the points of its axis in the order of their position along it.
// docs/reconstruction.md, "Centre lines", step 10.
#pragma once

#include <cstddef>

#include "reconstruct/bsg/bsg.h"

namespace ramus::bsg {

// For every chain of one-child nodes between a fork or the root and the next fork or tip, whose
// inner nodes of radius at least `min_radius` are not in order along the chord from its start to
// its end: the inner nodes' positions and radii are sorted by their coordinate along the chord
// (the nodes, their parents and every other field stay). Only chains whose inner nodes lie
// within half the chord's length of it are sorted: such a smooth chain turns by less than 180
// degrees, and its points are then in order along the chord. Chains that step back along the
// chord by more than three of their largest radii are left as they are: they turn back (two
// branches joined at their tips), they do not wind. Returns the number of chains sorted.
std::size_t order_chains_along_axes(Bsg& bsg, double min_radius);

// Chains that start behind their fork. On a thick stem the BSG's paths can reach a fork from
// above, so the chain that goes on from the fork first runs back down the stem's axis (thick_oak
// from one station: 4-7 such chains per scan, up to 3.8 stem radii behind the fork), and a mesh
// of it turns back on itself at the fork (a neck). The leading inner nodes of a fork's child
// chain that lie behind the fork (along the chord from the fork to the chain's end), of radius
// at least `min_radius` and within the fork's radius of the stem below it (the chain from the
// fork or root below), move into that stem: the chain goes on from its first node ahead, and the
// stem's inner nodes and the moved ones are linked in order along the stem's chord. Nodes keep
// their positions, radii and fits; the nodes are put in parent-first order again. Returns the
// number of nodes moved.
std::size_t return_nodes_behind_forks(Bsg& bsg, double min_radius);

}  // namespace ramus::bsg
