#include <catch2/catch.hpp>
#include <limits>
#include <memory>

#include "format_test_util.h"
#include "formats/point_cloud_io.h"

using namespace ramus;
using namespace ramus::test;

namespace {

PointCloud pcd(const std::string& s, ReadReport* report = nullptr, const ReadOptions& o = {}) {
  return read_point_cloud_bytes(s, Format::kPcd, "t.pcd", o, report);
}

const char* kAscii =
    "# .PCD v0.7 - Point Cloud Data file format\n"
    "VERSION 0.7\n"
    "FIELDS x y z rgb normal_x normal_y normal_z intensity\n"
    "SIZE 4 4 4 4 4 4 4 4\n"
    "TYPE F F F F F F F F\n"
    "COUNT 1 1 1 1 1 1 1 1\n"
    "WIDTH 3\n"
    "HEIGHT 1\n"
    "VIEWPOINT 10 20 1.5 1 0 0 0\n"
    "POINTS 3\n"
    "DATA ascii\n"
    "1 2 3 4.2108e+06 0 0 1 0.5\n"
    "4 5 6 4.2108e+06 1 0 0 0.25\n"
    "7 8 9 4.2108e+06 0 1 0 1\n";

// Binary: x as F4, y as F8, z as I4 (mm), a 3-wide histogram, intensity U2, classification U1.
std::string binary_pcd(std::size_t points) {
  Bytes b;
  b.text(
      "VERSION .7\nFIELDS x y z hist intensity classification\nSIZE 4 8 4 4 2 1\n"
      "TYPE F F I F U U\nCOUNT 1 1 1 3 1 1\nWIDTH " +
      std::to_string(points) + "\nHEIGHT 1\nDATA binary\n");
  for (std::size_t i = 0; i < points; ++i) {
    b.put<float>(float(i) + 0.5f).put<double>(-double(i)).put<std::int32_t>(std::int32_t(i * 7));
    b.put<float>(1).put<float>(2).put<float>(3);
    b.put<std::uint16_t>(std::uint16_t(100 + i)).put<std::uint8_t>(std::uint8_t(i % 3));
  }
  return b.str();
}

}  // namespace

TEST_CASE("pcd: ascii with normals intensity and a viewpoint", "[pcd]") {
  ReadReport report;
  PointCloud c = read_point_cloud_bytes(kAscii, Format::kAuto, "cloud.dat", {}, &report);
  CHECK(report.format == Format::kPcd);
  CHECK(report.variant == "DATA ascii");
  REQUIRE(c.size() == 3);
  CHECK(c.world(2) == Vec3{7, 8, 9});
  REQUIRE(c.normals.size() == 3);
  CHECK(c.normals[1] == Vec3f{1, 0, 0});
  CHECK(c.intensity[0] == 0.5f);
  REQUIRE(c.scanner);
  CHECK(*c.scanner == Vec3{10, 20, 1.5});
  // PCL's default viewpoint means "not given".
  std::string s = kAscii;
  s.replace(s.find("VIEWPOINT 10 20 1.5"), 19, "VIEWPOINT 0 0 0");
  CHECK(!pcd(s).scanner);
}

TEST_CASE("pcd: binary with mixed field types and arrays", "[pcd]") {
  PointCloud c = pcd(binary_pcd(4));
  REQUIRE(c.size() == 4);
  for (std::size_t i = 0; i < 4; ++i) {
    CHECK(c.world(i) == Vec3{double(i) + 0.5, -double(i), double(i * 7)});
    CHECK(c.intensity[i] == float(100 + i));
    CHECK(c.classification[i] == i % 3);
  }
}

TEST_CASE("pcd: header errors name the line", "[pcd][errors]") {
  std::string s = kAscii;
  s.replace(s.find("SIZE 4 4 4 4 4 4 4 4"), 20, "SIZE 4 4 4 4 4 4 4");
  CHECK(error_of([&] { pcd(s); }) == "t.pcd: line 4: SIZE has 7 entries but FIELDS has 8");
  s = kAscii;
  s.replace(s.find("POINTS 3"), 8, "POINTS 4");
  CHECK(error_of([&] { pcd(s); }) == "t.pcd: line 11: POINTS 4 differs from WIDTH x HEIGHT = 3");
  s = kAscii;
  s.replace(s.find("DATA ascii"), 10, "DATA binary_compressed");
  CHECK(error_of([&] { pcd(s); })
            .find("t.pcd: line 11: DATA binary_compressed (LZF) is not "
                  "supported") == 0);
  s = kAscii;
  s.replace(s.find("TYPE F F F"), 10, "TYPE F X F");
  CHECK(error_of([&] { pcd(s); }) == "t.pcd: line 5: TYPE must be F, I or U, found 'X'");
  CHECK(error_of([] { pcd("FIELDS x y\nSIZE 4 4\nTYPE F F\nWIDTH 1\nDATA ascii\n1 2\n"); }) ==
        "t.pcd: line 5: FIELDS has no 'z' field (with COUNT 1)");
  CHECK(error_of([] { pcd("VERSION 0.7\nFIELDS x y z\n"); }) ==
        "t.pcd: line 2: the file ends before the 'DATA' line");
}

TEST_CASE("pcd: body errors name the line or byte", "[pcd][errors]") {
  std::string s = kAscii;
  s[s.find("4 5 6 4.2108e+06")] = 'q';
  CHECK(error_of([&] { pcd(s); }) == "t.pcd: line 13: expected a number for field 'x', found 'q'");
  std::string cut = std::string(kAscii).substr(0, std::string(kAscii).find("7 8 9"));
  CHECK(error_of([&] { pcd(cut); }) ==
        "t.pcd: line 14: the file ends after 2 of the 3 points the header announces");
  std::string b = binary_pcd(3);
  std::string e = error_of([&] { pcd(b.substr(0, b.size() - 1)); });
  CHECK(e.find("point 2 of 3 is cut off") != std::string::npos);
  CHECK(e.find("t.pcd: byte ") == 0);
}

TEST_CASE("pcd: organized clouds with NaN points are skipped and counted", "[pcd]") {
  ReadReport report;
  PointCloud c =
      pcd("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 2\nHEIGHT 2\nDATA ascii\n"
          "1 2 3\nnan nan nan\n4 5 6\nnan nan nan\n",
          &report);
  CHECK(c.size() == 2);
  CHECK(report.skipped == 2);
}

TEST_CASE("pcd: truncation at every length gives an error or a valid prefix", "[pcd][fuzz]") {
  const std::string full = binary_pcd(3);
  for (std::size_t len = 0; len <= full.size(); ++len) {
    std::unique_ptr<char[]> buf(new char[len + 1]);
    std::memcpy(buf.get(), full.data(), len);
    try {
      PointCloud c = read_point_cloud_bytes(std::string_view(buf.get(), len), Format::kPcd, "t");
      CHECK(len == full.size());
      CHECK(c.size() == 3);
    } catch (const FormatError&) {
    }
  }
  const std::string text = kAscii;
  for (std::size_t len = 0; len <= text.size(); ++len) {
    try {
      PointCloud c = pcd(text.substr(0, len));
      CHECK(c.size() == 3);
    } catch (const FormatError&) {
    }
  }
}
