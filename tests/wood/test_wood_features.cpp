// The building blocks of the wood/leaf separation: covariance features on shapes whose answer is
// known (cylinders are linear, discs planar, balls scattering), the two-Gaussian EM fit, Otsu's
// threshold and the voxel subsample.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cmath>

#include "core/rng.h"
#include "reconstruct/wood/features.h"
#include "reconstruct/wood/mixture.h"
#include "reconstruct/wood/otsu.h"
#include "reconstruct/wood/voxel_subsample.h"

using namespace ramus;
using namespace ramus::wood;

namespace {

// Points on the surface of a cylinder of `radius` along `axis` through the origin, length 2.
std::vector<Eigen::Vector3d> cylinder(double radius, const Eigen::Vector3d& axis, Rng& rng,
                                      int n = 4000) {
  const Eigen::Vector3d a = axis.normalized();
  const Eigen::Vector3d u = a.unitOrthogonal(), v = a.cross(u);
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i < n; ++i) {
    const double t = rng.uniform(-1, 1), phi = rng.uniform(0, 2 * M_PI);
    p.push_back(t * a + radius * (std::cos(phi) * u + std::sin(phi) * v));
  }
  return p;
}

std::vector<Eigen::Vector3d> disc(double radius, const Eigen::Vector3d& normal, Rng& rng,
                                  int n = 4000) {
  const Eigen::Vector3d u = normal.unitOrthogonal(), v = normal.normalized().cross(u);
  std::vector<Eigen::Vector3d> p;
  while (int(p.size()) < n) {
    const double x = rng.uniform(-radius, radius), y = rng.uniform(-radius, radius);
    if (x * x + y * y <= radius * radius) p.push_back(x * u + y * v);
  }
  return p;
}

std::vector<Eigen::Vector3d> ball(double radius, Rng& rng, int n = 4000) {
  std::vector<Eigen::Vector3d> p;
  while (int(p.size()) < n) {
    const Eigen::Vector3d q(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    if (q.squaredNorm() <= 1) p.push_back(radius * q);
  }
  return p;
}

// Features of the neighbourhood of radius r around `centre` (the origin by default).
Eigenfeatures at_centre(const std::vector<Eigen::Vector3d>& p, double r,
                        const Eigen::Vector3d& centre = Eigen::Vector3d::Zero()) {
  std::vector<std::uint32_t> ids;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if ((p[i] - centre).norm() <= r) ids.push_back(std::uint32_t(i));
  }
  return eigenfeatures(p, ids.data(), ids.size());
}

}  // namespace

TEST_CASE("wood features: a thin cylinder is linear and its verticality follows its axis",
          "[wood]") {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    Rng rng(seed);
    const Eigenfeatures up = at_centre(cylinder(0.03, {0, 0, 1}, rng), 0.3);
    CHECK(up.linearity > 0.9);
    CHECK(up.verticality > 0.99);
    const Eigenfeatures side = at_centre(cylinder(0.03, {1, 1, 0}, rng), 0.3);
    CHECK(side.linearity > 0.9);
    CHECK(side.verticality < 0.01);
    CHECK(std::abs(up.linearity + up.planarity + up.scattering - 1) < 1e-5);
  }
}

TEST_CASE("wood features: a disc is planar, a ball scatters, a wide cylinder is not scattered",
          "[wood]") {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    Rng rng(seed);
    const Eigenfeatures d = at_centre(disc(1.0, {0.3, -0.2, 1}, rng), 0.3);
    CHECK(d.planarity > 0.7);  // a round patch: l1 close to l2
    CHECK(d.linearity < 0.3);
    CHECK(d.scattering < 0.01);
    const Eigenfeatures b = at_centre(ball(1.0, rng), 0.5);
    CHECK(b.scattering > 0.6);
    CHECK(b.linearity < 0.3);
    // Bark of a thick stem at a radius below the stem's: a surface, never volumetric.
    const std::vector<Eigen::Vector3d> stem = cylinder(0.5, {0, 0, 1}, rng, 20000);
    const Eigenfeatures trunk = at_centre(stem, 0.3, stem[0]);
    CHECK(trunk.scattering < 0.1);
  }
}

TEST_CASE("wood features: every point's features are those of its radius neighbourhood", "[wood]") {
  Rng rng(5);
  const std::vector<Eigen::Vector3d> p = cylinder(0.05, {0, 1, 1}, rng, 600);
  const auto f = multiscale_features(p, {0.1, 0.3}, 1000);
  for (std::size_t i = 0; i < p.size(); i += 37) {
    for (int s = 0; s < 2; ++s) {
      std::vector<std::uint32_t> ids;
      const double r = s == 0 ? 0.1 : 0.3;
      for (std::size_t j = 0; j < p.size(); ++j) {
        if ((p[j] - p[i]).norm() <= r) ids.push_back(std::uint32_t(j));
      }
      const Eigenfeatures e = eigenfeatures(p, ids.data(), ids.size());
      CHECK(std::abs(f[s][i].linearity - e.linearity) < 1e-4);
      CHECK(std::abs(f[s][i].scattering - e.scattering) < 1e-4);
    }
  }
}

TEST_CASE("wood features: degenerate neighbourhoods are fully scattering, never NaN", "[wood]") {
  const std::vector<Eigen::Vector3d> same(5, Eigen::Vector3d(1, 2, 3));
  const std::uint32_t ids[5] = {0, 1, 2, 3, 4};
  const Eigenfeatures f = eigenfeatures(same, ids, 5);
  CHECK(f.scattering == 1.0f);
  CHECK(eigenfeatures(same, ids, 2).scattering == 1.0f);
  const auto all = multiscale_features(same, {0.1, 1.0});
  REQUIRE(all.size() == 2);
  for (const auto& scale : all) {
    for (const Eigenfeatures& e : scale) CHECK(std::isfinite(e.linearity));
  }
  CHECK(multiscale_features({}, {1.0})[0].empty());
}

TEST_CASE("wood mixture: EM recovers two separated Gaussians over many seeds", "[wood]") {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    Rng rng(seed);
    std::vector<double> x;
    for (int i = 0; i < 3000; ++i) x.push_back(rng.normal(0.0, 1.0));
    for (int i = 0; i < 2000; ++i) x.push_back(rng.normal(6.0, 0.5));
    const Mixture2 m = fit_mixture2(x);
    CHECK(std::abs(m.mean[0] - 0.0) < 0.1);
    CHECK(std::abs(m.mean[1] - 6.0) < 0.1);
    CHECK(std::abs(m.weight[1] - 0.4) < 0.02);
    CHECK(std::abs(std::sqrt(m.variance[1]) - 0.5) < 0.05);
    CHECK(m.separation() > 6);
    CHECK(m.posterior_high(5.0) > 0.99);
    CHECK(m.posterior_high(1.0) < 0.01);
  }
}

TEST_CASE("wood mixture: one mode gives a small separation, constant input does not break",
          "[wood]") {
  Rng rng(3);
  std::vector<double> x;
  for (int i = 0; i < 5000; ++i) x.push_back(rng.normal(2.0, 1.0));
  CHECK(fit_mixture2(x).separation() < 2.0);
  const Mixture2 c = fit_mixture2(std::vector<double>(100, 0.25));
  CHECK(c.mean[0] == 0.25);
  CHECK(c.mean[1] == 0.25);
  CHECK(c.separation() == 0.0);
  CHECK(fit_mixture2({}).separation() == 0.0);
}

TEST_CASE("wood Otsu: the threshold falls between two modes", "[wood]") {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    Rng rng(seed);
    std::vector<double> x;
    for (int i = 0; i < 3000; ++i) x.push_back(rng.normal(0.0, 0.5));
    for (int i = 0; i < 1000; ++i) x.push_back(rng.normal(5.0, 0.5));
    const OtsuThreshold t = otsu_threshold(x);
    CHECK(t.threshold > 1.5);
    CHECK(t.threshold < 3.5);
    CHECK(std::abs(t.upper_fraction - 0.25) < 0.01);
    CHECK(t.separability > 0.9);
  }
  const OtsuThreshold flat = otsu_threshold(std::vector<double>(10, 1.0));
  CHECK(flat.separability == 0.0);
  CHECK(flat.upper_fraction == 0.0);
}

TEST_CASE("wood voxel subsample: every kept point in one cell, centroids inside cells", "[wood]") {
  Rng rng(9);
  std::vector<Eigen::Vector3d> p;
  std::vector<std::uint8_t> keep;
  for (int i = 0; i < 2000; ++i) {
    p.emplace_back(rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1));
    keep.push_back(i % 7 != 0);
  }
  const VoxelSubsample v = voxel_subsample(p, keep, 0.25);
  CHECK(v.centroids.size() <= 64);
  std::size_t total = 0;
  for (std::uint32_t c : v.count) total += c;
  CHECK(total == std::size_t(std::count(keep.begin(), keep.end(), 1)));
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!keep[i]) {
      CHECK(v.cell[i] == VoxelSubsample::kNoCell);
      continue;
    }
    REQUIRE(v.cell[i] < v.centroids.size());
    CHECK((v.centroids[v.cell[i]] - p[i]).cwiseAbs().maxCoeff() < 0.25);
  }
}
