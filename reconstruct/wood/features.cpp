#include "reconstruct/wood/features.h"

#include <tbb/parallel_for.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "reconstruct/bsg/kdtree.h"

namespace ramus::wood {

namespace {

// Demantke et al. 2011, Eq. 2-4, from a neighbourhood's covariance.
Eigenfeatures from_covariance(const Eigen::Matrix3d& cov) {
  Eigenfeatures f;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es;
  es.computeDirect(cov);
  // Ascending eigenvalues: l3 <= l2 <= l1; tiny negative round-off clamped to zero.
  const double l3 = std::max(es.eigenvalues()[0], 0.0);
  const double l2 = std::max(es.eigenvalues()[1], 0.0);
  const double l1 = std::max(es.eigenvalues()[2], 0.0);
  if (!(l1 > 0) || !std::isfinite(l1)) return f;
  f.linearity = float((l1 - l2) / l1);
  f.planarity = float((l2 - l3) / l1);
  f.scattering = float(l3 / l1);
  f.verticality = float(std::abs(es.eigenvectors().col(2).z()));
  f.normal_z = float(std::abs(es.eigenvectors().col(0).z()));
  return f;
}

}  // namespace

Eigenfeatures eigenfeatures(const std::vector<Eigen::Vector3d>& pts, const std::uint32_t* ids,
                            std::size_t n) {
  if (n < 3) return {};
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (std::size_t j = 0; j < n; ++j) mean += pts[ids[j]];
  mean /= double(n);
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (std::size_t j = 0; j < n; ++j) {
    const Eigen::Vector3d d = pts[ids[j]] - mean;
    cov.noalias() += d * d.transpose();
  }
  return from_covariance(cov / double(n));
}

std::vector<std::vector<Eigenfeatures>> multiscale_features(const std::vector<Eigen::Vector3d>& pts,
                                                            const std::vector<double>& radii,
                                                            std::size_t max_neighbours) {
  std::vector<std::vector<Eigenfeatures>> out(radii.size(), std::vector<Eigenfeatures>(pts.size()));
  if (pts.empty() || radii.empty()) return out;
  const bsg::PointIndex index(pts);
  const std::size_t k = std::max<std::size_t>(3, max_neighbours);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pts.size(), 256),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      std::vector<std::uint32_t> ids(k);
                      std::vector<double> d2(k);
                      for (std::size_t i = range.begin(); i != range.end(); ++i) {
                        const std::size_t n = index.knn(pts[i], k, ids.data(), d2.data());
                        // Neighbours come nearest first, so each radius takes a prefix.
                        std::size_t m = 0;
                        for (std::size_t s = 0; s < radii.size(); ++s) {
                          const double r2 = radii[s] * radii[s];
                          while (m < n && d2[m] <= r2) ++m;
                          out[s][i] = eigenfeatures(pts, ids.data(), m);
                        }
                      }
                    });
  return out;
}

}  // namespace ramus::wood
