// Simulated forest plots with known trees (`ramus scan GRAMMAR... --forest N --area WxH`): trees
// placed on a ground plane, scanned together from a grid of stations, so that tree detection
// and tiled reconstruction can be scored against the truth (docs/scale.md).
#pragma once

#include <cstdint>
#include <vector>

#include "backends/scanner/scanner.h"
#include "core/skeleton.h"

namespace ramus::scanner {

// The plot is [0, width] x [0, depth] on the ground plane z = 0.
struct PlotArea {
  double width = 0, depth = 0;
};

// Half the crown's width: the largest horizontal distance of a node from the tree's root.
double crown_radius(const Skeleton& tree);

// The tree moved so that its root stands at (x, y, 0).
Skeleton plant(const Skeleton& tree, double x, double y);

// Random base positions in the area for trees of these crown radii, in order, each at least
// max(r_i, r_j) (a crown radius) from every other so that no base stands under another tree's
// crown centre; a tree's crown may reach over the plot's edge. Positions come from
// Rng::stream(seed, ...) only. Throws ScanError naming the tree that found no place after
// `attempts` random tries (the plot is too small or too full).
std::vector<Vec3> place_trees(const std::vector<double>& crown_radii, const PlotArea& area,
                              std::uint64_t seed, int attempts = 20000);

struct ForestScanOptions {
  double station_spacing = 10.0;  // stations on a grid of cells about this wide, one per centre
  double station_height = 1.5;    // tripod height above the ground
  double clearance = 1.0;         // a station is moved this far at least from every tree base
  // Rays hitting the ground are kept with this probability: the ground only has to be there for
  // terrain removal, and at full density it would outnumber the trees' points many times.
  double ground_keep = 0.1;
  ScanOptions scan;  // angular_step, noise, max_range, leaves, seed; `from` is set here
};

// The stations of the grid (moved off tree bases), in row order.
std::vector<Vec3> station_grid(const PlotArea& area, const std::vector<Vec3>& bases,
                               const ForestScanOptions& options);

// Meshes the planted trees and the ground (the plot grown by the largest crown radius on every
// side) and scans them from station_grid's stations. The cloud's scanner is the first station.
ScanResult scan_forest(const std::vector<Skeleton>& planted, const PlotArea& area,
                       const ForestScanOptions& options);

}  // namespace ramus::scanner
