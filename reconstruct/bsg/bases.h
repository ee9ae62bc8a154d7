// Tree base identification (Livny et al. 2010, section 4.1): points projected on the ground
// plane (z up) form dense clusters around trunks; the low terrain layer is removed and one root
// is chosen per dense cluster, which separates several trees without pre-segmentation.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace ramus::bsg {

struct BaseParams {
  double ground_band;      // thickness of the terrain layer above the ground envelope
  double cell;             // edge of the 2D density grid
  double slab;             // height of the slab above the terrain that is projected
  double max_trunk_width;  // dense clusters wider than this are not trunks
  double min_separation;   // a weaker cluster closer than this to a stronger one is not a tree
  bool remove_terrain;
};

struct Bases {
  std::vector<std::uint8_t> terrain;   // per point: 1 if removed as terrain
  std::vector<Eigen::Vector3d> roots;  // one base position per tree (relative coordinates)
  std::vector<double> reach;           // per root: half the width of its trunk's footprint
  std::string note;                    // why there is no root, when there is none
};

// Only points with keep[i] != 0 take part.
Bases find_bases(const std::vector<Eigen::Vector3d>& points, const std::vector<std::uint8_t>& keep,
                 const BaseParams& params);

}  // namespace ramus::bsg
