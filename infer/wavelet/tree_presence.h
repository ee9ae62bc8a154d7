// Whether a scan can hold a tree at all, checked before any inference.
//
// Friedman & Stamos 2013 assume a scan of one tree (III-A roots it at its lowest point). On a
// flat patch of ground, a wall or a handful of points the pipeline would still write a grammar
// -- of noise -- so these inputs are refused with what is missing: points, height above the
// base, or extent in the third dimension.
#pragma once

#include <cstddef>

#include "infer/wavelet/alignment.h"

namespace ramus::wavelet {

// A tree needs a trunk and branches: fewer points cannot show both.
inline constexpr std::size_t kMinTreePoints = 20;
// Height over horizontal extent below which nothing rises above the base (ground, a roof).
inline constexpr double kMinHeightShare = 0.02;
// Thickness (smallest principal standard deviation) over the largest below which the points lie
// on one plane (a wall, a sloping ground patch); the real scans here have 0.17 or more.
inline constexpr double kMinThickness = 0.01;

// Throws std::invalid_argument naming what the cloud lacks.
void require_tree(const AlignedCloud& cloud);

}  // namespace ramus::wavelet
