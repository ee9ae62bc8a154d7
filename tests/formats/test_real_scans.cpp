// The real scans in ../shared/data (see its SOURCES.md): counts, extents, precision, timings.
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>

#include "format_test_util.h"
#include "formats/point_cloud_io.h"

using namespace ramus;
using namespace ramus::test;

namespace {

Vec3 extent(const PointCloud& c) {
  Vec3f lo{1e30f, 1e30f, 1e30f}, hi{-1e30f, -1e30f, -1e30f};
  for (const Vec3f& p : c.positions) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  return Vec3(hi - lo);
}

double read_ms(const std::string& path, PointCloud& out) {
  auto t0 = std::chrono::steady_clock::now();
  out = read_point_cloud(path);
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

TEST_CASE("real scans: text files read with the published point counts", "[real]") {
  struct Case {
    const char* file;
    std::size_t points;
    double ex, ey, ez;  // extents from SOURCES.md (m), 0 where not published
  };
  const Case cases[] = {
      {"adtree_tree1.xyz", 11855, 2.5, 3.7, 5.5},
      {"adtree_ahn3_delft.xyz", 2488, 9.5, 10.5, 13.1},
      {"rtwig_cloud.txt", 14667, 0, 0, 0},
      {"plantscan3d_A3B4.asc", 20903, 1.7, 2.2, 5.0},
  };
  for (const Case& k : cases) {
    INFO(k.file);
    PointCloud c;
    double ms = read_ms(shared_data(k.file), c);
    CHECK(c.size() == k.points);
    CHECK(ms < 1000);  // milliseconds in practice; a loose guard against pathologies
    Vec3 e = extent(c);
    if (k.ex > 0) {
      CHECK(std::abs(e.x - k.ex) < 0.1);
      CHECK(std::abs(e.y - k.ey) < 0.1);
      CHECK(std::abs(e.z - k.ez) < 0.1);
    }
  }
  PointCloud rtwig = read_point_cloud(shared_data("rtwig_cloud.txt"));
  CHECK(std::abs(rtwig.offset.z - 254) < 3);
}

TEST_CASE("real scans: pytlidar LAS 1.4 format 6 with a zeroed header box", "[real][las]") {
  const std::string path = shared_data("pytlidar_tree_1.las");
  ReadReport report;
  PointCloud c = read_point_cloud(path, {}, &report);
  CHECK(report.variant == "LAS 1.4, point format 6, 30-byte records");
  REQUIRE(c.size() == 90239);
  Vec3 e = extent(c);
  CHECK(std::abs(e.x - 12.7) < 0.1);
  CHECK(std::abs(e.y - 18.2) < 0.1);
  CHECK(std::abs(e.z - 12.9) < 0.1);
  CHECK(c.offset.x > 1.17e6);
  CHECK(c.offset.y > 2.85e6);

  // Recompute every world coordinate in double straight from the records and compare with
  // offset + float position: recentring must keep the error far below a millimetre.
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  double scale[3], off[3];
  for (int k = 0; k < 3; ++k) {
    std::memcpy(&scale[k], bytes.data() + 131 + 8 * k, 8);
    std::memcpy(&off[k], bytes.data() + 155 + 8 * k, 8);
  }
  std::uint32_t start;
  std::memcpy(&start, bytes.data() + 96, 4);
  double worst = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    Vec3 w;
    for (int k = 0; k < 3; ++k) {
      std::int32_t v;
      std::memcpy(&v, bytes.data() + start + 30 * i + 4 * k, 4);
      w[k] = v * scale[k] + off[k];
    }
    worst = std::max(worst, distance(w, c.world(i)));
  }
  CHECK(worst < 1e-3);
  // Without recentring the float error would be tens of centimetres at 2.86e6 m.
  CHECK(double(float(2860000.123)) - 2860000.123 != Approx(0).margin(0.01));

  PointCloud timed;
  CHECK(read_ms(path, timed) < 1000);
}

