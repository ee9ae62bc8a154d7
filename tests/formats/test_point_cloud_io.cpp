#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "format_test_util.h"
#include "formats/point_cloud_io.h"

using namespace ramus;
using namespace ramus::test;
namespace fs = std::filesystem;

namespace {

PointCloud sample_cloud(Vec3 offset, bool channels) {
  PointCloud c;
  c.offset = offset;
  for (int i = 0; i < 25; ++i) {
    c.positions.push_back({float(i) * 0.37f - 4.1f, float(i % 5) * 1.013f, float(i) * 0.001f});
    if (channels) {
      c.normals.push_back(Vec3f(normalized(Vec3{double(i), 1.0, 2.0})));
      c.intensity.push_back(float(i) * 2.5f);
      c.classification.push_back(std::uint8_t(i % 7));
    }
  }
  return c;
}

void check_same(const PointCloud& a, const PointCloud& b, double tol) {
  REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) CHECK(distance(a.world(i), b.world(i)) <= tol);
  CHECK(a.normals == b.normals);
  CHECK(a.intensity == b.intensity);
  CHECK(a.classification == b.classification);
}

}  // namespace

TEST_CASE("point_cloud_io: format from extension and from content", "[io]") {
  CHECK(format_from_extension("a/b/scan.PLY") == Format::kPly);
  CHECK(format_from_extension("scan.csv") == Format::kXyz);
  CHECK(format_from_extension("scan.asc") == Format::kXyz);
  CHECK(format_from_extension("scan.laz") == Format::kLas);
  CHECK(format_from_extension("scan.pcd") == Format::kPcd);
  CHECK(format_from_extension("dir.v2/scan") == Format::kAuto);
  CHECK(sniff_format("ply\r\nformat") == Format::kPly);
  CHECK(sniff_format(std::string_view("LASF\0\0", 6)) == Format::kLas);
  CHECK(sniff_format("# .PCD v0.7\nVERSION 0.7\n") == Format::kPcd);
  CHECK(sniff_format("1 2 3\n") == Format::kAuto);
}

TEST_CASE("point_cloud_io: content wins over a misleading extension", "[io]") {
  auto dir = temp_dir("dispatch");
  const std::string ply = (dir / "really_ply.txt").string();
  write_point_cloud_ply(ply, sample_cloud({}, false));
  ReadReport report;
  CHECK(read_point_cloud(ply, {}, &report).size() == 25);
  CHECK(report.format == Format::kPly);
  // A .las that is not LAS gets the LAS reader's precise complaint.
  const std::string las = (dir / "fake.las").string();
  write_file_atomically(las, std::string_view("1 2 3\n"));
  CHECK(error_of([&] { read_point_cloud(las); }) ==
        las + ": byte 0: expected the LAS signature 'LASF', found '1 2 '");
  fs::remove_all(dir);
}

TEST_CASE("point_cloud_io: missing empty and directory paths are clear errors", "[io][errors]") {
  auto dir = temp_dir("missing");
  CHECK(error_of([&] {
          read_point_cloud((dir / "nope.ply").string());
        }).find("nope.ply: cannot open the file (No such file or directory)") != std::string::npos);
  CHECK(error_of([&] { read_point_cloud(dir.string()); }).find("is a directory") !=
        std::string::npos);
  const std::string empty = (dir / "empty.xyz").string();
  std::ofstream(empty).close();
  CHECK(error_of([&] { read_point_cloud(empty); }) == empty + ": the file is empty");
  fs::remove_all(dir);
}

TEST_CASE("point_cloud_io: PLY and XYZ writers round trip every channel", "[io][writers]") {
  auto dir = temp_dir("roundtrip");
  for (Vec3 offset : {Vec3{0, 0, 0}, Vec3{1180006, 2860009, 254}}) {
    const PointCloud c = sample_cloud(offset, true);
    for (bool binary : {true, false}) {
      const std::string path = (dir / (binary ? "b.ply" : "a.ply")).string();
      write_point_cloud_ply(path, c, binary);
      check_same(c, read_point_cloud(path), 1e-6);
    }
    const std::string xyz = (dir / "c.xyz").string();
    write_point_cloud_xyz(xyz, c);
    check_same(c, read_point_cloud(xyz), 1e-6);
  }
  // Large offsets are written as double world coordinates, small ones as float.
  CHECK(point_cloud_to_ply(sample_cloud({1e6, 0, 0}, false)).find("property double x") !=
        std::string::npos);
  CHECK(point_cloud_to_ply(sample_cloud({}, false)).find("property float x") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("point_cloud_io: writers refuse inconsistent channels", "[io][writers]") {
  PointCloud c = sample_cloud({}, true);
  c.intensity.pop_back();
  CHECK_THROWS_AS(point_cloud_to_ply(c), WriteError);
  CHECK_THROWS_AS(point_cloud_to_xyz(c), WriteError);
}

TEST_CASE("point_cloud_io: the offset is the whole-unit centre of the bounding box", "[io]") {
  PointCloud c = read_point_cloud_bytes("10.4 -3.6 0.2\n12.8 -1.0 0.4\n", Format::kXyz, "t");
  CHECK(c.offset == Vec3{12, -2, 0});
  CHECK(c.positions[0] == Vec3f(Vec3{10.4 - 12, -3.6 + 2, 0.2}));
}
