// Alignment and quantization of scans (infer/wavelet/alignment.h, voxelize.h; III-A).
#include <catch2/catch.hpp>
#include <cmath>

#include "infer/wavelet/alignment.h"
#include "infer/wavelet/voxelize.h"

using namespace ramus;
using namespace ramus::wavelet;

namespace {

PointCloud cloud_of(std::initializer_list<Vec3> pts, Vec3 offset = {}) {
  PointCloud c;
  c.offset = offset;
  for (const Vec3& p : pts) c.positions.push_back(Vec3f(p));
  return c;
}

bool near(const Vec3& a, const Vec3& b, double eps = 1e-9) { return distance(a, b) < eps; }

}  // namespace

TEST_CASE("alignment: the root is the lowest point and the scanner direction becomes +y",
          "[wavelet]") {
  PointCloud c = cloud_of({{5, 5, 3}, {4, 6, 1}, {6, 4, 2}});
  AlignOptions o;
  o.scanner = Vec3{14, 6, 1.5};  // due +x of the root (4, 6, 1)
  AlignedCloud a = align_cloud(c, o);
  CHECK(a.alignment.source == ScannerSource::given);
  CHECK(a.alignment.warning.empty());
  CHECK(near(a.alignment.root, {4, 6, 1}));
  CHECK(near(a.points[1], {0, 0, 0}));
  // The scanner lies at -y in the aligned frame: the vector scanner -> root is +y.
  Vec3 s = a.alignment.to_aligned(*o.scanner);
  CHECK(s.x == Approx(0).margin(1e-9));
  CHECK(s.y == Approx(-10));
  CHECK(s.z == Approx(0.5));
  // Distances and heights are preserved; to_world inverts to_aligned.
  CHECK(a.points[0].z == Approx(2));
  CHECK(length(a.points[0]) == Approx(distance(Vec3{5, 5, 3}, Vec3{4, 6, 1})));
  CHECK(near(a.alignment.to_world(a.points[2]), {6, 4, 2}, 1e-6));
}

TEST_CASE("alignment: the scanner from the file then the centroid guess then the fallback",
          "[wavelet]") {
  PointCloud c = cloud_of({{0, 0, 0}, {0, -2, 1}, {0, -2, 2}});
  c.scanner = Vec3{0, -10, 0};
  AlignedCloud a = align_cloud(c);
  CHECK(a.alignment.source == ScannerSource::cloud);
  CHECK(near(a.alignment.scanner_dir, {0, 1, 0}));
  c.scanner.reset();
  a = align_cloud(c);
  // The centroid (0, -4/3) lies towards -y: the guessed scanner is there, the direction is +y.
  CHECK(a.alignment.source == ScannerSource::centroid);
  CHECK_FALSE(a.alignment.warning.empty());
  CHECK(near(a.alignment.scanner_dir, {0, 1, 0}));
  PointCloud column = cloud_of({{1, 1, 0}, {1, 1, 1}, {1, 1, 2}});
  a = align_cloud(column);
  CHECK(a.alignment.source == ScannerSource::none);
  CHECK_FALSE(a.alignment.warning.empty());
  CHECK(a.alignment.angle == 0);
}

TEST_CASE("alignment: bad clouds give clear errors", "[wavelet]") {
  CHECK_THROWS_WITH(align_cloud(PointCloud{}), Catch::Contains("empty"));
  PointCloud c = cloud_of({{0, 0, 0}, {1, 1, 1}});
  c.positions[1].y = std::nanf("");
  CHECK_THROWS_WITH(align_cloud(c), Catch::Contains("point 1"));
}

TEST_CASE("voxelize: occupancy and density in a power-of-two cube", "[wavelet]") {
  PointCloud c =
      cloud_of({{0.5, 0.2, 0}, {0.5, 0.2, 0.1}, {0.5, 0.2, 0.05}, {3, 0.7, 8}, {-2, -0.3, 8}});
  c.scanner = Vec3{0.5, -10, 0};  // straight -y of the root: no rotation
  AlignedCloud a = align_cloud(c);
  VoxelizeOptions o;
  o.levels = 3;
  VoxelGrid g = voxelize(a, o);
  CHECK(g.n == 8);
  CHECK(g.voxel_size == Approx(1.0).epsilon(1e-6));  // extent 8 m over 8 voxels
  CHECK(g.origin.z == 0);
  CHECK(g.count_above(0) == 3);
  // Aligned: root at 0, the others at (2.5, 0.5, 8) and (-2.5, -0.5, 8); the cube is
  // [-4, 4] x [-4, 4] x [0, 8] (grown by 1e-9).
  CHECK(g.at(4, 4, 0) == 1.0);  // the root's voxel holds three points
  o.values = VoxelValues::density;
  VoxelGrid d = voxelize(a, o);
  CHECK(d.at(4, 4, 0) == 1.0);
  CHECK(d.at(6, 4, 7) == Approx(1.0 / 3));
  CHECK(d.at(1, 3, 7) == Approx(1.0 / 3));
}

TEST_CASE("voxelize: degenerate and far-away clouds", "[wavelet]") {
  VoxelizeOptions o;
  o.levels = 6;
  VoxelGrid one = voxelize(align_cloud(cloud_of({{1, 2, 3}})), o);
  CHECK(one.count_above(0) == 1);
  VoxelGrid same = voxelize(align_cloud(cloud_of({{1, 2, 3}, {1, 2, 3}, {1, 2, 3}})), o);
  CHECK(same.count_above(0) == 1);
  // UTM-scale offsets: the geometry relative to the root is what matters.
  PointCloud far = cloud_of({{0, 0, 0}, {0, 0, 10}, {3, 0, 5}}, {1.18e6, 2.86e6, 100});
  far.scanner = Vec3{1.18e6, 2.86e6 - 50, 100};
  VoxelGrid g = voxelize(align_cloud(far), o);
  CHECK(g.count_above(0) == 3);
  CHECK(g.voxel_size == Approx(10.0 / 64).epsilon(1e-6));
}

TEST_CASE("voxelize: grid sides must be powers of two", "[wavelet]") {
  CHECK(levels_for_side(64) == 6);
  CHECK(levels_for_side(1) == 0);
  CHECK_THROWS_WITH(levels_for_side(100), Catch::Contains("not a power of two"));
  CHECK_THROWS_AS(levels_for_side(0), std::invalid_argument);
  CHECK_THROWS_AS(levels_for_side(4096), std::invalid_argument);
  VoxelizeOptions o;
  o.levels = 11;
  CHECK_THROWS_AS(voxelize(align_cloud(cloud_of({{0, 0, 0}})), o), std::invalid_argument);
  CHECK_THROWS_AS(parse_voxel_values("counts"), std::invalid_argument);
  CHECK(parse_voxel_values("density") == VoxelValues::density);
}
