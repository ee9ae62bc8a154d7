// Tree bases of a forest plot from stems in a slice above the ground, the way forest-inventory
// tools find trees in terrestrial scans (a slice, usually around breast height, above a ground
// model, clustered in the ground plane; e.g. Liang et al. 2016, "Terrestrial laser scanning in
// forest inventories", ISPRS J. Photogramm. 115, section 4.2). Livny et al.'s density clusters
// (bsg/bases) compare every trunk with the densest one (by the bark their points sample, which
// keeps most far trunks of a plot; by points alone, a trunk 2 m from a station holds fifty times
// the points of one 15 m away and the far trunks are lost); here a stem is an occupied footprint,
// whatever its density.
//
// Everything is on grids aligned to world coordinate 0, and a stem depends only on the points
// near it, so a tile whose buffer covers the stem finds the same base as the whole plot
// (docs/scale.md).
#pragma once

#include <cstdint>
#include <vector>

#include "core/point_cloud.h"
#include "core/vec3.h"

namespace ramus::forest {

struct StemOptions {
  double ground_cell = 1.0;  // ground model: lowest point of each cell, min over 3 x 3 cells
  double ground_band = 0.1;  // points this close above the ground model are ground
  // The slice above the ground whose footprints are stems: low, under the first whorls of young
  // conifers (the example grammars branch from 0.6 m), above the ground's noise.
  double slice_low = 0.2, slice_high = 0.6;
  double cell = 0.05;           // footprint grid of the slice
  double max_stem_width = 1.2;  // wider footprints are not stems (shrubs, walls)
  double min_stem_width = 0.1;  // narrower ones are twigs (inventories count stems from 5-10 cm)
  double min_separation = 0.6;  // a weaker footprint nearer than this to a stronger one is a
                                // branch or the far side of the same stem
  int min_points = 10;          // fewer points in the slice: noise, a twig
};

struct StemBases {
  std::vector<Vec3> bases;           // world coordinates: footprint centre on the ground model
  std::vector<std::uint8_t> ground;  // per point: 1 when in the ground band
};

StemBases find_stem_bases(const PointCloud& cloud, const StemOptions& options = {});

// `cloud` without its ground points (what reconstruct() gets together with the bases).
PointCloud without_ground(const PointCloud& cloud, const std::vector<std::uint8_t>& ground);

}  // namespace ramus::forest
