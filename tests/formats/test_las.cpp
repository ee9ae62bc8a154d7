#include <catch2/catch.hpp>
#include <cmath>
#include <memory>

#include "format_test_util.h"
#include "formats/point_cloud_io.h"

using namespace ramus;
using namespace ramus::test;

namespace {

std::vector<LasPoint> sample_points() {
  return {{1000, -2000, 3000, 10, 2}, {-5000, 7000, 0, 200, 5}, {123456, 654321, -777, 65535, 31}};
}

PointCloud read_las_bytes(const std::string& bytes, ReadReport* report = nullptr) {
  return read_point_cloud_bytes(bytes, Format::kLas, "t.las", {}, report);
}

}  // namespace

TEST_CASE("las: every version and point format reads positions intensity and class", "[las]") {
  const std::pair<int, int> variants[] = {{0, 0}, {1, 1}, {2, 0}, {2, 1}, {2, 2}, {2, 3}, {3, 4},
                                          {3, 5}, {4, 6}, {4, 7}, {4, 8}, {4, 9}, {4, 10}};
  for (auto [minor, format] : variants) {
    for (std::size_t extra : {std::size_t(0), std::size_t(7)}) {
      LasSpec spec;
      spec.minor = minor;
      spec.format = format;
      spec.extra_bytes = extra;
      spec.offset[0] = 100;
      spec.offset[2] = -3;
      spec.vlrs = extra ? 2 : 0;
      ReadReport report;
      PointCloud c = read_las_bytes(make_las(spec, sample_points()), &report);
      INFO("LAS 1." << minor << " format " << format << " extra " << extra);
      REQUIRE(c.size() == 3);
      CHECK(report.variant.find("point format " + std::to_string(format)) != std::string::npos);
      const auto pts = sample_points();
      for (std::size_t i = 0; i < 3; ++i) {
        Vec3 want{pts[i].x * 0.001 + 100, pts[i].y * 0.001, pts[i].z * 0.001 - 3};
        CHECK(distance(c.world(i), want) < 1e-4);  // float resolution ~650 m from centre
        CHECK(c.intensity[i] == float(pts[i].intensity));
        CHECK(c.classification[i] == pts[i].classification);  // flag bits masked off
      }
    }
  }
}

TEST_CASE("las: bounds come from the points and UTM-scale offsets keep sub-millimetre floats",
          "[las]") {
  LasSpec spec;
  spec.minor = 4;
  spec.format = 6;
  spec.offset[0] = 1180000;
  spec.offset[1] = 2860000;
  std::vector<LasPoint> pts;
  for (int i = 0; i < 50; ++i)
    pts.push_back({i * 12345 - 300000, i * 54321 - 900000, i * 1001, 0, 0});
  PointCloud c = read_las_bytes(make_las(spec, pts));
  REQUIRE(c.size() == 50);
  // Offset is the whole-unit-rounded centre of the points, not the (zeroed) header box.
  Vec3 lo{1180000 - 300.0, 2860000 - 900.0, 0},
      hi{lo.x + 49 * 12.345, lo.y + 49 * 54.321, 49 * 1.001};
  for (int k = 0; k < 3; ++k) CHECK(c.offset[k] == std::round((lo[k] + hi[k]) / 2));
  double worst = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    Vec3 want{1180000 + pts[i].x * 0.001, 2860000 + pts[i].y * 0.001, pts[i].z * 0.001};
    worst = std::max(worst, distance(c.world(i), want));
  }
  CHECK(worst < 1e-4);
  CHECK(c.intensity.empty());  // all-zero channels are dropped
  CHECK(c.classification.empty());
}

TEST_CASE("las: header errors name the byte and what was expected", "[las][errors]") {
  LasSpec spec;
  spec.minor = 4;
  spec.format = 6;
  std::string good = make_las(spec, sample_points());

  std::string s = good;
  poke<std::uint16_t>(s, 105, 20);
  CHECK(error_of([&] { read_las_bytes(s); }) ==
        "t.las: byte 105: point data record length 20 is smaller than the 30 bytes of point "
        "format 6");
  s = good;
  s[25] = 7;
  CHECK(error_of([&] { read_las_bytes(s); }).find("byte 24: unsupported LAS version 1.7") !=
        std::string::npos);
  s = good;
  s[104] = 11;
  CHECK(error_of([&] {
          read_las_bytes(s);
        }).find("byte 104: unknown point data record format 11") != std::string::npos);
  s = good;
  poke<double>(s, 139, 0.0);
  CHECK(error_of([&] { read_las_bytes(s); }).find("byte 139: y scale factor is zero") !=
        std::string::npos);
  s = good;
  poke<std::uint32_t>(s, 96, 1u << 30);
  CHECK(error_of([&] { read_las_bytes(s); }).find("byte 96: offset to point data") !=
        std::string::npos);
  s = good;
  poke<std::uint64_t>(s, 247, 4);
  CHECK(error_of([&] { read_las_bytes(s); }) ==
        "t.las: byte 465: the header announces 4 points of 30 bytes but the file holds only 3 "
        "complete records");
  s = good;
  s.replace(0, 4, "LASX");
  CHECK(error_of([&] { read_las_bytes(s); }) ==
        "t.las: byte 0: expected the LAS signature 'LASF', found 'LASX'");
  s = good;
  poke<std::uint32_t>(s, 100, 1);  // a VLR announced where there is no room for one
  CHECK(error_of([&] {
          read_las_bytes(s);
        }).find("byte 375: variable length record 1 of 1 runs past") != std::string::npos);
}

TEST_CASE("las: 1.4 files use the 64-bit point count over the legacy one", "[las]") {
  LasSpec spec;
  spec.minor = 4;
  spec.format = 3;  // a legacy format in a 1.4 file may leave the 32-bit count zero
  spec.zero_legacy_count = true;
  CHECK(read_las_bytes(make_las(spec, sample_points())).size() == 3);
  spec.zero_legacy_count = false;
  std::string s = make_las(spec, sample_points());
  poke<std::uint32_t>(s, 107, 2);  // a stale legacy count loses to the 64-bit one
  CHECK(read_las_bytes(s).size() == 3);
  // Before 1.4 there is only the legacy count.
  spec.minor = 2;
  s = make_las(spec, sample_points());
  poke<std::uint32_t>(s, 107, 2);
  CHECK(read_las_bytes(s).size() == 2);
}

TEST_CASE("las: zero points is a clear error", "[las][errors]") {
  LasSpec spec;
  CHECK(error_of([&] { read_las_bytes(make_las(spec, {})); }) ==
        "t.las: no points: the file holds no point data");
}

TEST_CASE("las: a compression bit without a laszip VLR, or a broken laszip VLR, is an error",
          "[las][laz]") {
  LasSpec spec;
  std::string s = make_las(spec, sample_points());
  s[104] = char(0x80 | 0);
  std::string e = error_of([&] { read_las_bytes(s); });
  CHECK(e.find("t.las: byte 104: point format byte 0x80 marks the points LAZ-compressed but "
               "there is no 'laszip encoded' variable length record") == 0);

  // A laszip VLR (even without the format bit) makes the points compressed: this one has 8
  // bytes, too short for its fixed fields.
  spec.vlrs = 1;
  s = make_las(spec, sample_points());
  s.replace(227 + 2, 16, std::string("laszip encoded\0\0", 16));
  poke<std::uint16_t>(s, 227 + 18, 22204);
  CHECK(error_of([&] { read_las_bytes(s); }) ==
        "t.las: byte 281: the laszip record has 8 bytes, expected at least 34");
}

TEST_CASE("las: truncation at every length gives an error never a crash", "[las][fuzz]") {
  LasSpec spec;
  spec.minor = 4;
  spec.format = 7;
  spec.extra_bytes = 3;
  spec.vlrs = 1;
  const std::string full = make_las(spec, sample_points());
  REQUIRE(read_las_bytes(full).size() == 3);
  for (std::size_t len = 0; len < full.size(); ++len) {
    // A heap block of exactly `len` bytes so a sanitizer build sees any overrun.
    std::unique_ptr<char[]> buf(new char[len + 1]);
    std::memcpy(buf.get(), full.data(), len);
    INFO("length " << len);
    CHECK_THROWS_AS(read_point_cloud_bytes(std::string_view(buf.get(), len), Format::kLas, "t.las"),
                    FormatError);
  }
}
