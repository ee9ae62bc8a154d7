// Points with no other point near them, left out before quantization (III-A).
//
// The voxel cube of III-A is the smallest cube holding every point, so one stray return far from
// the tree (pytlidar_tree_1.las has one 15 m out at 12 m height) stretches the cube, coarsens
// every cell and becomes a significant coefficient of its own that the spanning trees (III-E)
// must join to the tree with an edge through empty air. A point is isolated when no other point
// lies in its cell or the 26 around it, cells being 1/16 of the cloud's largest extent: far
// enough that a sparse scan keeps every twig, near enough to leave out a stray return.
#pragma once

#include <cstddef>
#include <optional>

#include "infer/wavelet/alignment.h"

namespace ramus::wavelet {

inline constexpr int kIsolationCells = 16;  // cells along the largest extent

// The cloud without its isolated points (same alignment); nothing when there is none (the
// cloud is used as it is, not copied).
std::optional<AlignedCloud> without_isolated_points(const AlignedCloud& cloud);

}  // namespace ramus::wavelet
