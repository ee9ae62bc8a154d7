// Centre lines along chains: where the cross-section of a node cannot be fitted (a one-sided scan
// of a limb whose slab sees a short, flat arc; a spur chain on the bark of a thick limb whose
// radius hint is a twig's; a skeleton direction that cuts the branch obliquely), the chain the
// node lies on is cut into pieces of a few radii and a cylinder with a free axis direction is
// fitted to all points around each piece (cylinder_fit.h; TreeQSM's segments and cylinders,
// Raumonen et al. 2013, section 2.3). The piece's unfitted nodes move onto the accepted axis.
// docs/reconstruction.md, "Centre lines".
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "reconstruct/bsg/centre_line.h"
#include "reconstruct/bsg/kdtree.h"

namespace ramus::bsg {

// pos: current positions (the slab fits applied); fitted / fitted_radius: the slab fits, which
// are kept. Nodes placed here get fitted = 1 and their cylinder's radius. Returns how many.
std::size_t fit_chain_cylinders(std::vector<Eigen::Vector3d>& pos,
                                const std::vector<std::uint32_t>& parent,
                                const std::vector<double>& hint, std::vector<std::uint8_t>& fitted,
                                std::vector<double>& fitted_radius, const PointIndex& index,
                                const std::vector<Eigen::Vector3d>& samples,
                                const std::vector<double>& weight, const CentreLineParams& p,
                                double noise);

// A node neither a cross-section nor a cylinder placed (not a tip, hint at least `thin`) between
// two fitted nodes, at most `steps` nodes up and down its stem, moves onto the segment between
// them when it lies within 1.5 x their radius (plus two spacings) of it; where the way down
// leaves the node's branch for the stem it grows from, onto the branch's own axis (through the
// fitted node above and the next one out) instead. At a fork the stem goes on into the heaviest
// child, unless that child's fits are thinner than the pipe model allows a stem's continuation
// (kPipeChild of the fit below) and a straighter child's are not. Run by fit_chain_cylinders and
// again after the one-sided sections (one_sided_sections.h).
std::size_t bridge_unfitted(std::vector<Eigen::Vector3d>& pos,
                            const std::vector<std::uint32_t>& parent,
                            const std::vector<double>& hint, std::vector<std::uint8_t>& fitted,
                            std::vector<double>& fitted_radius, double spacing, double thin,
                            int steps = 4);

}  // namespace ramus::bsg
