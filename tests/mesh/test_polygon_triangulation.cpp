// Triangulation of the turtle's polygons (mesh/polygon_triangulation.h).
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "mesh/polygon_triangulation.h"

using namespace ramus;
using namespace ramus::mesh;

namespace {

// The summed area of the triangles, in 3D.
double area(const std::vector<Vec3>& v, const PolygonTriangles& t) {
  double a = 0;
  for (std::size_t k = 0; k + 2 < t.indices.size(); k += 3) {
    a += length(
             cross(v[t.indices[k + 1]] - v[t.indices[k]], v[t.indices[k + 2]] - v[t.indices[k]])) /
         2;
  }
  return a;
}

// Whether every triangle winds counter-clockwise about the normal (none flipped).
bool all_facing(const std::vector<Vec3>& v, const PolygonTriangles& t) {
  for (std::size_t k = 0; k + 2 < t.indices.size(); k += 3) {
    const Vec3 n =
        cross(v[t.indices[k + 1]] - v[t.indices[k]], v[t.indices[k + 2]] - v[t.indices[k]]);
    if (dot(n, t.normal) <= 0) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("triangulation: a concave outline by ear clipping, area kept", "[mesh][polygon]") {
  // An L in the x-z plane (area 3), recorded clockwise seen from +y.
  const std::vector<Vec3> l = {{0, 0, 0}, {0, 0, 2}, {1, 0, 2}, {1, 0, 1}, {2, 0, 1}, {2, 0, 0}};
  const PolygonTriangles t = triangulate_polygon(l);
  REQUIRE(t.indices.size() == 3 * (l.size() - 2));
  CHECK(area(l, t) == Approx(3));
  CHECK(all_facing(l, t));
  CHECK(std::abs(t.normal.y) == Approx(1));
  REQUIRE(t.uvs.size() == l.size());
  for (const auto& uv : t.uvs) {
    CHECK(uv[0] >= 0.0f);
    CHECK(uv[0] <= 1.0f);
    CHECK(uv[1] >= 0.0f);
    CHECK(uv[1] <= 1.0f);
  }
}

TEST_CASE("triangulation: a mildly non-planar outline in its best-fit plane", "[mesh][polygon]") {
  // A regular hexagon around z, its vertices lifted alternately by +-0.05.
  std::vector<Vec3> h;
  for (int k = 0; k < 6; ++k) {
    const double a = k * M_PI / 3;
    h.push_back({std::cos(a), std::sin(a), k % 2 ? 0.05 : -0.05});
  }
  const PolygonTriangles t = triangulate_polygon(h);
  REQUIRE(t.indices.size() == 12);
  CHECK(t.normal.z == Approx(1));
  CHECK(all_facing(h, t));
  CHECK(area(h, t) == Approx(3 * std::sqrt(3.0) / 2).epsilon(0.01));
}

TEST_CASE("triangulation: outlines without area give no triangles", "[mesh][polygon]") {
  CHECK(triangulate_polygon({{0, 0, 0}, {1, 0, 0}}).indices.empty());
  CHECK(triangulate_polygon({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}).indices.empty());
}
