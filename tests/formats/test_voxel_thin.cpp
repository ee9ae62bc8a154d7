// Voxel thinning while a file is read (ReadOptions::thin) keeps exactly the points that thinning
// the cloud read whole keeps (thin_cloud), in every format, whether the reader's guess of the
// offset holds (one pass) or not (two), and with a thinner shared across files (`ramus tile`).
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <set>
#include <vector>

#include "core/rng.h"
#include "format_test_util.h"
#include "formats/las_file.h"
#include "formats/point_cloud_io.h"
#include "formats/voxel_thin.h"

using namespace ramus;
using namespace ramus::test;

namespace {

template <typename T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// Byte for byte: offset, positions and every channel.
void require_same(const PointCloud& a, const PointCloud& b) {
  REQUIRE(a.size() == b.size());
  REQUIRE(std::memcmp(&a.offset, &b.offset, sizeof a.offset) == 0);
  CHECK(same_bytes(a.positions, b.positions));
  CHECK(same_bytes(a.normals, b.normals));
  CHECK(same_bytes(a.intensity, b.intensity));
  CHECK(same_bytes(a.classification, b.classification));
  CHECK(a.scanner.has_value() == b.scanner.has_value());
}

ReadOptions thinning(double size, VoxelThinner* shared = nullptr) {
  ReadOptions o;
  o.thin = size;
  o.thinner = shared;
  return o;
}

// 20,000 points on a 1 mm lattice around (1000.4, 2000.6, 10), as LAS with a zero header box.
std::vector<LasPoint> lattice(std::int32_t x0) {
  std::vector<LasPoint> points;
  for (std::int32_t i = 0; i < 20000; ++i) {
    points.push_back({x0 + i % 40 * 1, 2000600 + i / 40 % 25, 10000 + i / 1000,
                      std::uint16_t(i % 7 == 0 ? 0 : i % 300), std::uint8_t(i % 3)});
  }
  return points;
}

}  // namespace

TEST_CASE("thinning while reading keeps the points of read-then-thin in the bundled scans",
          "[thin]") {
  for (const char* file : {"pytlidar_tree_1.las", "treels_spruce.laz", "adtree_tree1.xyz",
                           "adtree_ahn3_delft.xyz", "plantscan3d_A3B4.asc", "rtwig_cloud.txt"}) {
    const PointCloud whole = read_point_cloud(shared_data(file));
    for (double size : {0.004, 0.01, 0.05}) {
      INFO(file << " at " << size);
      ReadReport report;
      const PointCloud thinned = read_point_cloud(shared_data(file), thinning(size), &report);
      const PointCloud expected = thin_cloud(whole, size);
      require_same(thinned, expected);
      if (size == 0.05) CHECK(thinned.size() < whole.size());
      CHECK(report.points_read == thinned.size());
      CHECK(report.points_before_thinning == whole.size());
    }
  }
}

TEST_CASE("a LAS header's box saves the second pass, a stale one costs it, with the same points",
          "[thin]") {
  LasSpec spec;
  spec.minor = 4;
  spec.format = 6;
  spec.offset[0] = 0;
  std::string las = make_las(spec, lattice(1000400));  // header box zero: offset guess (0,0,0)
  const PointCloud whole = read_point_cloud_bytes(las, Format::kLas, "lattice.las");
  REQUIRE(whole.offset == Vec3(1000, 2001, 10));
  ReadReport stale;
  const PointCloud a =
      read_point_cloud_bytes(las, Format::kLas, "lattice.las", thinning(0.01), &stale);
  CHECK(stale.passes == 2);
  require_same(a, thin_cloud(whole, 0.01));
  // A lattice point lies on a cube face every centimetre, so which cube it falls in depends on
  // the narrowing: thinning the file's exact coordinates keeps other points. (The first thinned
  // reader thinned what it believed to be the narrowed point, and GCC's vectorizer had folded
  // the narrowing away.)
  VoxelThinner exact(0.01);
  std::size_t exact_kept = 0;
  for (const LasPoint& q : lattice(1000400)) {
    exact_kept += exact.keep(Vec3(q.x * 0.001, q.y * 0.001, q.z * 0.001));
  }
  CHECK(exact_kept != a.size());

  // The header box of the points (max x, min x, max y, min y, max z, min z).
  const double box[6] = {1000.439, 1000.4, 2000.624, 2000.6, 10.019, 10.0};
  for (int k = 0; k < 6; ++k) poke<double>(las, 179 + 8 * k, box[k]);
  ReadReport fresh;
  const PointCloud b =
      read_point_cloud_bytes(las, Format::kLas, "lattice.las", thinning(0.01), &fresh);
  CHECK(fresh.passes == 1);
  require_same(b, a);

  // LAZ of the same records: the decoder streams chunk by chunk, the same points come out.
  const std::string laz = compress_las(las, "lattice.las", 5000);
  require_same(read_point_cloud_bytes(laz, Format::kLas, "lattice.laz", thinning(0.01)), a);
}

TEST_CASE("thinning while reading PLY and PCD keeps the points of read-then-thin", "[thin]") {
  const PointCloud whole = read_point_cloud(shared_data("adtree_tree1.xyz"));
  for (bool binary : {true, false}) {
    const std::string ply = point_cloud_to_ply(whole, binary);
    const PointCloud read = read_point_cloud_bytes(ply, Format::kPly, "t.ply");
    ReadReport report;
    require_same(read_point_cloud_bytes(ply, Format::kPly, "t.ply", thinning(0.02), &report),
                 thin_cloud(read, 0.02));
    CHECK(report.passes == 2);  // no header box: a first pass measures it
  }
  std::string pcd =
      "VERSION .7\nFIELDS x y z intensity\nSIZE 4 4 4 4\nTYPE F F F F\n"
      "COUNT 1 1 1 1\nWIDTH 300\nHEIGHT 1\nPOINTS 300\nDATA ascii\n";
  for (int i = 0; i < 300; ++i) {
    pcd += std::to_string(5 + i % 10 * 0.007) + " " + std::to_string(7 + i / 10 * 0.003) + " " +
           std::to_string(0.5 + i % 13 * 0.011) + " " + std::to_string(i) + "\n";
  }
  const PointCloud read = read_point_cloud_bytes(pcd, Format::kPcd, "t.pcd");
  require_same(read_point_cloud_bytes(pcd, Format::kPcd, "t.pcd", thinning(0.02)),
               thin_cloud(read, 0.02));
}

TEST_CASE(
    "a thinner shared by files keeps what one thinner over the clouds in turn keeps, "
    "also when a file is read twice",
    "[thin]") {
  LasSpec spec;
  spec.minor = 4;
  spec.format = 6;
  // Overlapping lattices: the second file's first pass (stale box) takes cubes the first file
  // left free, which its second pass must find free again.
  const std::string one = make_las(spec, lattice(1000400));
  const std::string two = make_las(spec, lattice(1000425));
  VoxelThinner expected_thinner(0.01);
  std::vector<Vec3f> expected;
  for (const std::string* f : {&one, &two}) {
    const PointCloud c = read_point_cloud_bytes(*f, Format::kLas, "f.las");
    for (std::size_t i = 0; i < c.size(); ++i) {
      if (expected_thinner.keep(c.world(i))) expected.push_back(c.positions[i]);
    }
  }
  VoxelThinner shared(0.01);
  std::vector<Vec3f> kept;
  for (const std::string* f : {&one, &two}) {
    ReadReport report;
    const PointCloud c =
        read_point_cloud_bytes(*f, Format::kLas, "f.las", thinning(0.01, &shared), &report);
    CHECK(report.passes == 2);
    kept.insert(kept.end(), c.positions.begin(), c.positions.end());
  }
  CHECK(shared.cells() == expected_thinner.cells());
  CHECK(same_bytes(kept, expected));
}

TEST_CASE("thinning keeps a channel that is zero in every kept point but not in all", "[thin]") {
  LasSpec spec;
  spec.minor = 4;
  spec.format = 6;
  std::vector<LasPoint> points;
  for (int i = 0; i < 10; ++i) points.push_back({i * 100, 0, 0, std::uint16_t(i % 2), 0});
  const std::string las = make_las(spec, points);
  // Cubes of 1 m hold all ten points: the first, intensity 0, is kept.
  const PointCloud c = read_point_cloud_bytes(las, Format::kLas, "i.las", thinning(1.0));
  REQUIRE(c.size() == 1);
  CHECK(c.intensity == std::vector<float>{0.0f});
  CHECK(c.classification.empty());
  require_same(c, thin_cloud(read_point_cloud_bytes(las, Format::kLas, "i.las"), 1.0));
}

TEST_CASE("the thinner's cube set: packed near cubes, far cubes, growth and undo", "[thin]") {
  // Against a std::set of cube indices: cubes near the first (packed in 64 bits), cubes more
  // than 2^20 cubes away (the fallback set), enough of them to grow the table several times,
  // and undo_since_mark() (backward-shift deletion) followed by the same and other cubes.
  Rng rng(7);
  VoxelThinner thinner(1.0);
  std::set<std::array<std::int64_t, 3>> reference;
  auto cube = [&](bool far) {
    const double reach = far ? 3e6 : 300;
    return Vec3(std::floor(rng.uniform(-reach, reach)), std::floor(rng.uniform(-reach, reach)),
                std::floor(rng.uniform(-reach / 10, reach / 10))) +
           Vec3(0.5, 0.5, 0.5);
  };
  auto key = [](const Vec3& p) {
    return std::array<std::int64_t, 3>{std::int64_t(std::floor(p.x)), std::int64_t(std::floor(p.y)),
                                       std::int64_t(std::floor(p.z))};
  };
  std::vector<Vec3> seen;
  for (int i = 0; i < 60000; ++i) {
    const Vec3 p =
        i % 50 == 0 && !seen.empty() ? seen[std::size_t(i) % seen.size()] : cube(i % 7 == 0);
    seen.push_back(p);
    REQUIRE(thinner.keep(p) == reference.insert(key(p)).second);
  }
  REQUIRE(thinner.cells() == reference.size());
  thinner.mark();
  std::vector<Vec3> later;
  for (int i = 0; i < 30000; ++i)
    later.push_back(i % 3 == 0 ? seen[std::size_t(i) * 2] : cube(i % 5 == 0));
  for (const Vec3& p : later) thinner.keep(p);
  thinner.undo_since_mark();
  thinner.commit();
  CHECK(thinner.cells() == reference.size());
  for (const Vec3& p : seen) CHECK_FALSE(thinner.keep(p));  // all still there
  for (const Vec3& p : later) REQUIRE(thinner.keep(p) == reference.insert(key(p)).second);
  CHECK(thinner.cells() == reference.size());
}
