// Local covariance (eigenvalue) features of a point's neighbourhood, the dimensionality
// descriptors of Demantke, Mallet, David & Vallet, "Dimensionality based scale selection in 3D
// lidar point clouds", ISPRS Archives XXXVIII-5/W12 (2011), Eq. 2-4, as used for leaf/wood
// separation by Vicari, Disney, Wilkes, Burt, Calders & Woodgate, "Leaf and wood classification
// framework for terrestrial LiDAR point clouds", Methods Ecol. Evol. 10 (2019).
//
// With the eigenvalues l1 >= l2 >= l3 >= 0 of the covariance of a neighbourhood,
//   linearity  = (l1 - l2) / l1,  planarity = (l2 - l3) / l1,  scattering = l3 / l1
// (the three sum to 1), and verticality = |e1 . z|, the vertical component of the principal
// direction e1 (1 along an upright stem, 0 along a horizontal branch).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace ramus::wood {

struct Eigenfeatures {
  float linearity = 0, planarity = 0, scattering = 1, verticality = 0;
  // |z| of the normal (the least eigenvector): 1 on a horizontal surface, 0 on a vertical one
  // (verticality is of the principal direction; ground_surface.h).
  float normal_z = 0;
};

// Features of the neighbourhood `pts[ids[0..n)]`; a degenerate one (fewer than 3 points, or all
// coincident) is fully scattering.
Eigenfeatures eigenfeatures(const std::vector<Eigen::Vector3d>& pts, const std::uint32_t* ids,
                            std::size_t n);

// Features of every point of `pts` at each neighbourhood radius in `radii` (ascending): a point's
// neighbourhood at radius r is every point within r of it, at most `max_neighbours` of the
// nearest. Result [s][i]: scale s, point i. Parallel, deterministic.
std::vector<std::vector<Eigenfeatures>> multiscale_features(const std::vector<Eigen::Vector3d>& pts,
                                                            const std::vector<double>& radii,
                                                            std::size_t max_neighbours = 96);

}  // namespace ramus::wood
