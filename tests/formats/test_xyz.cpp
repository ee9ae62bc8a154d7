#include <catch2/catch.hpp>
#include <limits>

#include "format_test_util.h"
#include "formats/point_cloud_io.h"

using namespace ramus;
using namespace ramus::test;

namespace {

PointCloud xyz(const std::string& s, ReadReport* report = nullptr, const ReadOptions& o = {}) {
  return read_point_cloud_bytes(s, Format::kXyz, "t.xyz", o, report);
}

}  // namespace

TEST_CASE("xyz: whitespace columns with comments blank lines and CRLF", "[xyz]") {
  std::string s =
      "# a comment\r\n\r\n// another\r\n1 2 3\r\n  4\t5   6  \r\n\r\n+7 8e0 -9.5E+1 extra 99\r\n";
  PointCloud c = xyz(s);
  REQUIRE(c.size() == 3);
  CHECK(c.world(0) == Vec3{1, 2, 3});
  CHECK(c.world(1) == Vec3{4, 5, 6});
  CHECK(c.world(2) == Vec3{7, 8, -95});
  CHECK(c.normals.empty());
  CHECK(c.intensity.empty());
}

TEST_CASE("xyz: a UTF-8 byte order mark is not a header", "[xyz]") {
  CHECK(xyz("\xEF\xBB\xBF"
            "1 2 3\n4 5 6\n")
            .size() == 2);
}

TEST_CASE("xyz: extra columns are ignored without a header", "[xyz]") {
  PointCloud c = xyz("1 2 3 0 0 1 77\n4 5 6 1 0 0 78\n");
  REQUIRE(c.size() == 2);
  CHECK(c.normals.empty());
  CHECK(c.intensity.empty());
}

TEST_CASE("xyz: CSV with a header names the columns", "[xyz]") {
  ReadReport report;
  PointCloud c = xyz("Intensity,X,Y,Z,class\n10,1,2,3,2\n20,4,5,6,5\n", &report);
  REQUIRE(c.size() == 2);
  CHECK(c.world(1) == Vec3{4, 5, 6});
  REQUIRE(c.intensity.size() == 2);
  CHECK(c.intensity[1] == 20);
  REQUIRE(c.classification.size() == 2);
  CHECK(c.classification[0] == 2);
  CHECK(report.variant == "comma-separated, columns named by a header");

  PointCloud d = xyz("x;y;z;nx;ny;nz\n1;2;3;0;0;1\n");
  REQUIRE(d.normals.size() == 1);
  CHECK(d.normals[0] == Vec3f{0, 0, 1});

  // CloudCompare's comment header.
  PointCloud e = xyz("//X,Y,Z,Nx,Ny,Nz,scalar_Intensity\n1,2,3,1,0,0,0.5\n");
  REQUIRE(e.normals.size() == 1);
  CHECK(e.normals[0] == Vec3f{1, 0, 0});
  CHECK(e.intensity[0] == 0.5f);

  // Prose comments that mention x, y and z are not headers.
  PointCloud g = xyz("# exported x and y and z by some tool\n# x y\n1 2 3 4\n");
  CHECK(g.world(0) == Vec3{1, 2, 3});

  // A header of other names keeps x y z in the first three columns.
  PointCloud f = xyz("a b c d\n1 2 3 4\n");
  CHECK(f.world(0) == Vec3{1, 2, 3});
}

TEST_CASE("xyz: errors name the line and what was expected", "[xyz][errors]") {
  CHECK(error_of([] { xyz("1 2 3\n4 5 6\n7 8\n"); }) ==
        "t.xyz: line 3: expected 3 numbers, found 2 ('7 8')");
  CHECK(error_of([] { xyz("1 2 3\n4 abc 6\n"); }) ==
        "t.xyz: line 2: expected a number in column 2 (y), found 'abc'");
  CHECK(error_of([] { xyz("x,y,q\n1,2,3\n"); }) ==
        "t.xyz: line 1: the header names only some of the columns x, y and z");
  CHECK(error_of([] { xyz("x y z classification\n1 2 3 2.5\n"); }) ==
        "t.xyz: line 2: expected a whole number 0-255 for the classification, found '2.5'");
  CHECK(error_of([] { xyz("# only a comment\n\n"); }) ==
        "t.xyz: no points: the file holds no point data");
  CHECK(error_of([] { read_point_cloud_bytes("", Format::kXyz, "e.xyz"); }) ==
        "e.xyz: the file is empty");
  CHECK(error_of([] { xyz("1 2 3\nx y z\n"); }) ==
        "t.xyz: line 2: expected a number in column 1 (x), found 'x'");
  CHECK(error_of([] { xyz(std::string("1 2 3\n\x01\xff 2 3\n")); }) ==
        "t.xyz: line 2: expected a number in column 1 (x), found '\\x01\\xff'");
}

TEST_CASE("xyz: non-finite points are skipped and counted or rejected", "[xyz]") {
  ReadReport report;
  PointCloud c = xyz("1 2 3\nnan 0 0\n4 inf 6\n7 8 9\n", &report);
  CHECK(c.size() == 2);
  CHECK(report.skipped == 2);
  CHECK(report.points_read == 2);
  ReadOptions strict;
  strict.skip_non_finite = false;
  CHECK(error_of([&] { xyz("1 2 3\nnan 0 0\n", nullptr, strict); }) ==
        "t.xyz: line 2: the point has a non-finite coordinate");
  CHECK(error_of([] { xyz("nan nan nan\n"); }) ==
        "t.xyz: no points: all 1 points have non-finite (NaN or infinite) coordinates");
  CHECK(error_of([] { xyz("1e300 0 0\n-1e300 0 0\n"); }) ==
        "t.xyz: the points span 2e+300 units along x, more than single precision can hold around "
        "one offset");
  // Huge normals or intensities saturate to infinity instead of being undefined behaviour.
  CHECK(xyz("x y z intensity\n1 2 3 1e300\n").intensity[0] ==
        std::numeric_limits<float>::infinity());
  // Out-of-range numbers overflow to infinity like IEEE arithmetic, and are then skipped.
  CHECK(xyz("1 2 3\n1e999 0 0\n").size() == 1);
}

TEST_CASE("xyz: recentring keeps UTM-scale coordinates to the millimetre", "[xyz]") {
  PointCloud c = xyz("1180000.001 2860000.002 10.003\n1180012.704 2860018.205 22.906\n");
  CHECK(c.offset == Vec3{1180006, 2860009, 16});
  CHECK(distance(c.world(0), Vec3{1180000.001, 2860000.002, 10.003}) < 1e-5);
  CHECK(distance(c.world(1), Vec3{1180012.704, 2860018.205, 22.906}) < 1e-5);
}

TEST_CASE("xyz: truncation at every length gives an error or a valid prefix", "[xyz][fuzz]") {
  const std::string text = "x y z intensity\n1.5 2.5 3.5 1\n-4 5 6e1 2\n7 8 9 3\n";
  for (std::size_t len = 0; len <= text.size(); ++len) {
    try {
      PointCloud c = xyz(text.substr(0, len));
      CHECK(c.size() <= 3);
    } catch (const FormatError&) {
    }
  }
}
