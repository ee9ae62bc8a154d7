// The simulated scanner: sampling density, occlusion, noise, a beam of some width (mixed
// echoes), stations registered with an error, determinism and bad input.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "backends/scanner/scanner.h"
#include "core/rng.h"

using namespace ramus;
using scanner::ScanOptions;

namespace {

// A w x h rectangle in the plane y = y0, facing -y, with its lower left corner at (x0, y0, z0).
void add_wall(std::vector<Vec3>& v, std::vector<std::uint32_t>& idx, double x0, double y0,
              double z0, double w, double h) {
  const auto b = std::uint32_t(v.size());
  v.push_back({x0, y0, z0});
  v.push_back({x0 + w, y0, z0});
  v.push_back({x0 + w, y0, z0 + h});
  v.push_back({x0, y0, z0 + h});
  for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) idx.push_back(b + i);
}

}  // namespace

TEST_CASE("scanner: a facing wall is sampled at the requested density", "[scanner]") {
  std::vector<Vec3> v;
  std::vector<std::uint32_t> idx;
  add_wall(v, idx, -0.5, 10, -0.5, 1, 1);
  ScanOptions o;
  o.from = {{0, 0, 0}};
  o.density = 4000;
  const auto r = scanner::scan_triangles(v, idx, o);
  // About 4000 points on 1 square unit at range 10 (a little more at the wall's centre).
  CHECK(r.cloud.size() > 3400);
  CHECK(r.cloud.size() < 4800);
  REQUIRE(r.cloud.scanner.has_value());
  for (std::size_t i = 0; i < r.cloud.size(); ++i) {
    const Vec3 p = r.cloud.world(i);
    CHECK(std::abs(p.y - 10) < 1e-4);
    CHECK(std::abs(p.x) <= 0.5 + 1e-4);
  }
}

TEST_CASE("scanner: density falls off with range", "[scanner]") {
  std::vector<Vec3> v;
  std::vector<std::uint32_t> idx;
  add_wall(v, idx, -0.5, 5, -0.5, 1, 1);  // near
  add_wall(v, idx, 3, 10, -0.5, 1, 1);    // far, not behind the near one
  ScanOptions o;
  o.from = {{0, 0, 0}};
  o.density = 2000;
  const auto r = scanner::scan_triangles(v, idx, o);
  std::size_t near = 0, far = 0;
  for (std::size_t i = 0; i < r.cloud.size(); ++i) (r.cloud.world(i).y < 7 ? near : far)++;
  // Spacing grows linearly with range, so the far wall gets about a quarter as many points.
  const double ratio = double(far) / double(near);
  CHECK(ratio > 0.15);
  CHECK(ratio < 0.35);
}

TEST_CASE("scanner: a near wall occludes the one behind it", "[scanner]") {
  std::vector<Vec3> v;
  std::vector<std::uint32_t> idx;
  add_wall(v, idx, -0.5, 5, -0.5, 1, 1);
  add_wall(v, idx, -2, 10, -2, 4, 4);
  ScanOptions o;
  o.from = {{0, 0, 0}};
  o.density = 500;
  const auto r = scanner::scan_triangles(v, idx, o);
  std::size_t shadowed = 0, back = 0;
  for (std::size_t i = 0; i < r.cloud.size(); ++i) {
    const Vec3 p = r.cloud.world(i);
    if (p.y < 7) continue;
    ++back;
    // The near wall's shadow on the back wall is |x|, |z| < 1 (twice as far, twice as large).
    if (std::abs(p.x) < 0.95 && std::abs(p.z) < 0.95) ++shadowed;
  }
  CHECK(back > 1000);
  CHECK(shadowed == 0);
}

TEST_CASE("scanner: range noise is Gaussian and seeded", "[scanner]") {
  std::vector<Vec3> v;
  std::vector<std::uint32_t> idx;
  add_wall(v, idx, -0.5, 10, -0.5, 1, 1);
  ScanOptions o;
  o.from = {{0, 0, 0}};
  o.density = 3000;
  o.noise = 0.01;
  o.seed = 42;
  const auto a = scanner::scan_triangles(v, idx, o), b = scanner::scan_triangles(v, idx, o);
  REQUIRE(a.cloud.size() == b.cloud.size());
  double sum2 = 0;
  for (std::size_t i = 0; i < a.cloud.size(); ++i) {
    CHECK(a.cloud.positions[i] == b.cloud.positions[i]);
    const Vec3 p = a.cloud.world(i);
    const double range_error = length(p) - length(p) * 10 / p.y;  // along the ray
    sum2 += range_error * range_error;
  }
  const double sd = std::sqrt(sum2 / double(a.cloud.size()));
  CHECK(sd > 0.008);
  CHECK(sd < 0.012);
  o.seed = 43;
  const auto c = scanner::scan_triangles(v, idx, o);
  CHECK_FALSE(c.cloud.positions == a.cloud.positions);
}

TEST_CASE("scanner: a wide beam returns mixed points between a rod's edge and the wall behind",
          "[scanner]") {
  // A 2 cm rod 5 m away, a wall 0.5 m behind it; a 4 mrad beam is 2 cm wide at the rod.
  std::vector<Vec3> v;
  std::vector<std::uint32_t> idx;
  add_wall(v, idx, -0.01, 5, -0.5, 0.02, 1);
  add_wall(v, idx, -1, 5.5, -1, 2, 2);
  ScanOptions o;
  o.from = {{0, 0, 0}};
  o.density = 20000;
  auto between = [](const scanner::ScanResult& r) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < r.cloud.size(); ++i) {
      const double y = r.cloud.world(i).y;
      n += y > 5.02 && y < 5.48 ? 1 : 0;
    }
    return n;
  };
  auto widest_on_rod = [](const scanner::ScanResult& r) {
    double x = 0;
    for (std::size_t i = 0; i < r.cloud.size(); ++i) {
      const Vec3 p = r.cloud.world(i);
      if (p.y < 5.02) x = std::max(x, std::abs(p.x));
    }
    return x;
  };
  const auto line = scanner::scan_triangles(v, idx, o);
  CHECK(between(line) == 0);
  CHECK(widest_on_rod(line) <= 0.01 + 1e-6);
  o.beam_divergence = 0.004;
  const auto mixed = scanner::scan_triangles(v, idx, o);
  // One echo per beam: where the footprint covers the rod's edge and the wall, the point lies
  // between them.
  CHECK(between(mixed) > 20);
  const auto again = scanner::scan_triangles(v, idx, o);
  CHECK(again.cloud.positions == mixed.cloud.positions);
  // Echoes 0.5 m apart are parted by a 0.1 m range resolution: no point between, and a beam on
  // the edge returns from both surfaces.
  o.range_resolution = 0.1;
  const auto parted = scanner::scan_triangles(v, idx, o);
  CHECK(between(parted) == 0);
  CHECK(parted.cloud.size() > line.cloud.size());
  // A footprint that covers a little of the rod still returns from it: the rod looks wider.
  CHECK(widest_on_rod(parted) > 0.012);
  CHECK(widest_on_rod(parted) < 0.02);
}

TEST_CASE("scanner: stations after the first are shifted by the registration error", "[scanner]") {
  std::vector<Vec3> v;
  std::vector<std::uint32_t> idx;
  add_wall(v, idx, -0.5, 10, -0.5, 1, 1);
  ScanOptions o;
  o.from = {{0, 0, 0}};
  o.density = 1000;
  const std::size_t first = scanner::scan_triangles(v, idx, o).cloud.size();
  o.from.push_back({0.3, 0, 0});
  o.registration_error = 0.02;
  const auto r = scanner::scan_triangles(v, idx, o);
  REQUIRE(r.cloud.size() > first + 100);
  for (std::size_t i = 0; i < first; ++i) CHECK(std::abs(r.cloud.world(i).y - 10) < 1e-4);
  // The second station's wall is one rigid shift away from the first's.
  const double shift = r.cloud.world(first).y - 10;
  CHECK(std::abs(shift) > 1e-4);
  for (std::size_t i = first; i < r.cloud.size(); ++i) {
    CHECK(std::abs(r.cloud.world(i).y - 10 - shift) < 1e-4);
  }
}

TEST_CASE("scanner: a skeleton is scanned on its bark", "[scanner]") {
  Skeleton s;
  SkeletonNode root;
  root.position = {0, 0, 0};
  root.radius = 0.2;
  s.add(root);
  SkeletonNode top;
  top.position = {0, 0, 4};
  top.radius = 0.1;
  top.parent = 0;
  s.add(top);
  ScanOptions o;
  o.from = {{0, -8, 1}, {7, 4, 1}};
  o.density = 1000;
  const auto r = scanner::scan_skeleton(s, o);
  REQUIRE(r.cloud.size() > 500);
  for (std::size_t i = 0; i < r.cloud.size(); ++i) {
    const Vec3 p = r.cloud.world(i);
    const double radial = std::hypot(p.x, p.y);
    const double expected = 0.2 - 0.1 * std::clamp(p.z / 4, 0.0, 1.0);
    // The tube is a polygon around the circle; caps may add points inside it.
    CHECK(radial <= expected + 1e-3);
  }
}

TEST_CASE("scanner: a georeferenced skeleton is scanned at millimetre precision", "[scanner]") {
  // The trunk of the test above at UTM-sized coordinates: the mesh is built about a local
  // origin, so the bark the rays hit is where it is in double precision, not on float32's
  // 0.25 m grid.
  const Vec3 utm{1180000.37, 2860000.81, 312.4};
  Skeleton s;
  SkeletonNode root;
  root.position = utm;
  root.radius = 0.2;
  s.add(root);
  SkeletonNode top;
  top.position = utm + Vec3{0, 0, 4};
  top.radius = 0.1;
  top.parent = 0;
  s.add(top);
  ScanOptions o;
  o.from = {utm + Vec3{0, -8, 1}};
  o.density = 1000;
  const auto r = scanner::scan_skeleton(s, o);
  REQUIRE(r.cloud.size() > 200);
  double worst = 0;
  for (std::size_t i = 0; i < r.cloud.size(); ++i) {
    const Vec3 p = r.cloud.world(i) - utm;
    const double expected = 0.2 - 0.1 * std::clamp(p.z / 4, 0.0, 1.0);
    worst = std::max(worst, std::hypot(p.x, p.y) - expected);
  }
  CHECK(worst <= 1e-3);
}

TEST_CASE("scanner: bad input gives clear errors", "[scanner]") {
  ScanOptions o;
  CHECK_THROWS_AS(scanner::scan_triangles({}, {}, o), scanner::ScanError);
  CHECK_THROWS_AS(scanner::scan_triangles({{0, 0, 0}}, {0, 1, 2}, o), scanner::ScanError);
  std::vector<Vec3> v;
  std::vector<std::uint32_t> idx;
  add_wall(v, idx, -0.5, 10, -0.5, 1, 1);
  o.beam_divergence = -1e-3;
  CHECK_THROWS_WITH(scanner::scan_triangles(v, idx, o), Catch::Contains("not negative"));
  o.beam_divergence = 0;
  o.registration_error = std::nan("");
  CHECK_THROWS_AS(scanner::scan_triangles(v, idx, o), scanner::ScanError);
  o.registration_error = 0;
  o.min_echo_fraction = 0;
  CHECK_THROWS_WITH(scanner::scan_triangles(v, idx, o), Catch::Contains("(0, 1]"));
  CHECK(scanner::parse_position("1,2.5,-3") == Vec3{1, 2.5, -3});
  CHECK_THROWS_WITH(scanner::parse_position("1,2"), Catch::Contains("x,y,z"));
  CHECK_THROWS_AS(scanner::parse_position("1,2,3,4"), scanner::ScanError);
  CHECK_THROWS_AS(scanner::parse_position("a,b,c"), scanner::ScanError);
}
