// Which points of the lowest layer are ground (reconstruct/bsg/ground_surface.h).
#include <catch2/catch.hpp>
#include <cmath>

#include "core/rng.h"
#include "reconstruct/bsg/ground_surface.h"

using namespace ramus;
using namespace ramus::bsg;

namespace {

std::size_t count(const std::vector<std::uint8_t>& v, std::size_t from, std::size_t to) {
  std::size_t n = 0;
  for (std::size_t i = from; i < to; ++i) n += v[i];
  return n;
}

// A 6 x 6 m field sloping 10 percent, with 1 cm of noise, `n` points.
void field(std::vector<Eigen::Vector3d>& out, int n, Rng& rng) {
  for (int k = 0; k < n; ++k) {
    const double x = rng.uniform(-3, 3), y = rng.uniform(-3, 3);
    out.emplace_back(x, y, 0.1 * x + rng.normal(0, 0.01));
  }
}

// A drooping branch end: points on a 7 mm twig that bends down from (x0, 0, 0.6) to near z = 0.1,
// with a pair of side twigs every 12 cm (a flat spray, as the conifer's branches are).
void drooping_spray(std::vector<Eigen::Vector3d>& out, double x0, double angle, Rng& rng) {
  const Eigen::Vector3d dir(std::cos(angle), std::sin(angle), 0), side(-dir.y(), dir.x(), 0);
  for (double s = 0; s < 0.9; s += 0.012) {
    const Eigen::Vector3d on = x0 * dir + s * dir + Eigen::Vector3d(0, 0, 0.6 - 0.6 * s * s);
    out.push_back(on + Eigen::Vector3d(rng.normal(0, 0.004), rng.normal(0, 0.004), 0));
    if (std::fmod(s, 0.12) < 0.012) {
      for (double t = 0.012; t < 0.25; t += 0.012) {
        for (double sign : {-1.0, 1.0})
          out.push_back(on + t * (0.7 * dir + sign * 0.7 * side) +
                        Eigen::Vector3d(0, 0, rng.normal(0, 0.004)));
      }
    }
  }
}

}  // namespace

TEST_CASE("ground surface: a sloping field is ground", "[reconstruct]") {
  Rng rng(5);
  std::vector<Eigen::Vector3d> pts;
  field(pts, 20000, rng);
  GroundSurfaceParams p;
  p.min_extent = 2.0;
  const std::vector<std::uint8_t> g = ground_surface(pts, p);
  CHECK(count(g, 0, pts.size()) >= 0.98 * double(pts.size()));
}

TEST_CASE("ground surface: the drooping sprays of a scan without ground are not", "[reconstruct]") {
  Rng rng(7);
  std::vector<Eigen::Vector3d> pts;
  for (int k = 0; k < 5; ++k) drooping_spray(pts, 0.3, 2 * M_PI * k / 5, rng);
  GroundSurfaceParams p;
  p.min_extent = 2.0;
  const std::vector<std::uint8_t> g = ground_surface(pts, p);
  INFO(pts.size() << " points");
  CHECK(count(g, 0, pts.size()) == 0);
}

TEST_CASE("ground surface: branch ends lying on a field stay, the field goes", "[reconstruct]") {
  Rng rng(11);
  std::vector<Eigen::Vector3d> pts;
  field(pts, 20000, rng);
  const std::size_t ground_end = pts.size();
  // Twigs resting a few centimetres above the field, each a line of points.
  for (int k = 0; k < 6; ++k) {
    const double a = 2 * M_PI * k / 6;
    for (double s = 0; s < 0.8; s += 0.01) {
      const double x = (1 + s) * std::cos(a), y = (1 + s) * std::sin(a);
      pts.emplace_back(x, y, 0.1 * x + 0.05 + rng.normal(0, 0.002));
    }
  }
  GroundSurfaceParams p;
  p.min_extent = 2.0;
  const std::vector<std::uint8_t> g = ground_surface(pts, p);
  CHECK(count(g, 0, ground_end) >= 0.98 * double(ground_end));
  // A twig is kept where its neighbourhood is its own line: at most the points where it comes
  // down among the field's go with it.
  CHECK(count(g, ground_end, pts.size()) <= (pts.size() - ground_end) / 4);
}

TEST_CASE("ground surface: too few points are no ground", "[reconstruct]") {
  std::vector<Eigen::Vector3d> pts;
  for (int k = 0; k < 10; ++k) pts.emplace_back(0.1 * k, 0.05 * (k % 3), 0);
  CHECK(count(ground_surface(pts, {}), 0, pts.size()) == 0);
  CHECK(ground_surface({}, {}).empty());
}
