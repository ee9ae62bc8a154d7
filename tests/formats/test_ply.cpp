#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>

#include "format_test_util.h"
#include "formats/point_cloud_io.h"

using namespace ramus;
using namespace ramus::test;

namespace {

struct Vtx {
  double x, y, z;
  float nx, ny, nz;
  std::uint16_t intensity;
  std::uint8_t cls;
};

const std::vector<Vtx> kVerts = {
    {1.5, -2, 3.25, 0, 0, 1, 100, 2},
    {1000.125, 2, -7.5, 1, 0, 0, 65535, 5},
    {-4, 8, 16, 0, 1, 0, 0, 0},
};

// A header with a face element *before* the vertices and the vertex properties shuffled:
// nz, a list, x as double, an unknown property, y as int, z as float, ...
std::string header(const char* encoding) {
  return std::string("ply\nformat ") + encoding +
         " 1.0\ncomment synthetic\nobj_info test\n"
         "element face 2\nproperty list uchar int vertex_indices\n"
         "element vertex 3\n"
         "property float nz\nproperty list uchar float junk\nproperty double x\n"
         "property float quality\nproperty int y\nproperty float z\nproperty float nx\n"
         "property ushort scalar_intensity\nproperty float ny\nproperty uchar classification\n"
         "element edge 1\nproperty int a\nproperty int b\n"
         "end_header\n";
}

std::string binary_ply(bool big) {
  Bytes b(big);
  b.text(header(big ? "binary_big_endian" : "binary_little_endian"));
  // faces: 3 and 4 indices
  b.put<std::uint8_t>(3).put<std::int32_t>(0).put<std::int32_t>(1).put<std::int32_t>(2);
  b.put<std::uint8_t>(4)
      .put<std::int32_t>(0)
      .put<std::int32_t>(1)
      .put<std::int32_t>(2)
      .put<std::int32_t>(0);
  for (std::size_t i = 0; i < kVerts.size(); ++i) {
    const Vtx& v = kVerts[i];
    b.put<float>(v.nz).put<std::uint8_t>(std::uint8_t(i));
    for (std::size_t k = 0; k < i; ++k) b.put<float>(9.5f);
    b.put<double>(v.x)
        .put<float>(0.25f)
        .put<std::int32_t>(std::int32_t(v.y))
        .put<float>(float(v.z));
    b.put<float>(v.nx).put<std::uint16_t>(v.intensity).put<float>(v.ny).put<std::uint8_t>(v.cls);
  }
  b.put<std::int32_t>(0).put<std::int32_t>(1);
  return b.str();
}

std::string ascii_ply() {
  std::string s = header("ascii");
  s += "3 0 1 2\n4 0 1 2 0\n";
  for (std::size_t i = 0; i < kVerts.size(); ++i) {
    const Vtx& v = kVerts[i];
    s += std::to_string(v.nz) + " " + std::to_string(i);
    for (std::size_t k = 0; k < i; ++k) s += " 9.5";
    char buf[200];
    std::snprintf(buf, sizeof buf, " %.17g 0.25 %d %.9g %g %u %g %u\n", v.x, int(v.y), v.z, v.nx,
                  unsigned(v.intensity), v.ny, unsigned(v.cls));
    s += buf;
  }
  return s + "0 1\n";
}

void check_cloud(const PointCloud& c) {
  REQUIRE(c.size() == kVerts.size());
  REQUIRE(c.normals.size() == kVerts.size());
  REQUIRE(c.intensity.size() == kVerts.size());
  REQUIRE(c.classification.size() == kVerts.size());
  for (std::size_t i = 0; i < kVerts.size(); ++i) {
    const Vtx& v = kVerts[i];
    CHECK(distance(c.world(i), Vec3{v.x, v.y, v.z}) < 1e-4);
    CHECK(c.normals[i] == Vec3f{v.nx, v.ny, v.nz});
    CHECK(c.intensity[i] == float(v.intensity));
    CHECK(c.classification[i] == v.cls);
  }
}

PointCloud ply(const std::string& s, const ReadOptions& o = {}) {
  return read_point_cloud_bytes(s, Format::kPly, "t.ply", o);
}

}  // namespace

TEST_CASE("ply: ascii and binary little and big endian with shuffled properties", "[ply]") {
  for (bool big : {false, true}) {
    ReadReport report;
    check_cloud(read_point_cloud_bytes(binary_ply(big), Format::kAuto, "x.bin", {}, &report));
    CHECK(report.format == Format::kPly);
    CHECK(report.variant == (big ? "binary_big_endian" : "binary_little_endian"));
  }
  check_cloud(ply(ascii_ply()));
}

TEST_CASE("ply: CRLF header and positions only", "[ply]") {
  std::string s =
      "ply\r\nformat ascii 1.0\r\nelement vertex 2\r\nproperty float x\r\nproperty float y\r\n"
      "property float z\r\nend_header\r\n1 2 3\r\n4 5 6\r\n";
  PointCloud c = ply(s);
  REQUIRE(c.size() == 2);
  CHECK(c.normals.empty());
  CHECK(c.world(1) == Vec3{4, 5, 6});
}

TEST_CASE("ply: header errors name the line", "[ply][errors]") {
  const std::string ok_tail =
      "element vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n1 2 3\n";
  CHECK(error_of([&] { ply("plx\n"); }) == "t.ply: line 1: expected 'ply' on the first line");
  CHECK(error_of([&] { ply("ply\n" + ok_tail); }) ==
        "t.ply: line 2: 'element' before the 'format' line");
  CHECK(error_of([&] { ply("ply\nformat binary_middle_endian 1.0\n" + ok_tail); }) ==
        "t.ply: line 2: expected ascii, binary_little_endian or binary_big_endian, found "
        "'binary_middle_endian'");
  CHECK(error_of([&] {
          ply("ply\nformat ascii 1.0\nelement vertex 1\nproperty flaot x\nend_header\n");
        }).find("t.ply: line 4: expected a property type") == 0);
  CHECK(error_of([&] { ply("ply\nformat ascii 1.0\nelement vertex many\n"); }) ==
        "t.ply: line 3: expected 'element <name> <count>', found count 'many'");
  CHECK(error_of([&] { ply("ply\nformat ascii 1.0\nproperty float x\n"); }) ==
        "t.ply: line 3: 'property' before any 'element'");
  CHECK(error_of([&] { ply("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"); }) ==
        "t.ply: line 4: the file ends before 'end_header'");
  CHECK(error_of([&] {
          ply("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
              "end_header\n1 2\n");
        }) == "t.ply: line 3: element 'vertex' has no scalar property 'z'");
  CHECK(error_of([&] { ply("ply\nformat ascii 1.0\nelement face 0\nend_header\n"); }) ==
        "t.ply: the header declares no 'vertex' element");
  // Found by fuzz_read_ply: a property-less vertex element of 512 million records, then a second
  // one with x, y, z; the reader took the first and filled memory.
  CHECK(error_of([&] {
          ply("ply\nformat binary_big_endian 1.0\nelement vertex 512222222\nelement vertex 3\n"
              "property float x\nproperty float y\nproperty float z\nend_header\n");
        }) == "t.ply: line 4: element 'vertex' is declared twice (first on line 3)");
  CHECK(error_of([&] {
          ply("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\n"
              "property float y\nproperty float z\nend_header\n");
        }) == "t.ply: no points: the file holds no point data");
}

TEST_CASE("ply: body errors name the line or byte", "[ply][errors]") {
  std::string s = ascii_ply();
  std::size_t at = s.find("1000.125");
  s.replace(at, 8, "abc");
  CHECK(error_of([&] { ply(s); }) ==
        "t.ply: line 25: expected a number for property 'x' of vertex 1, found 'abc'");
  std::string cut = ascii_ply().substr(0, ascii_ply().find("-4 0.25"));
  INFO(error_of([&] { ply(cut); }));
  CHECK(error_of([&] { ply(cut); }).find("the file ends where property 'x' of vertex 2 (of 3)") !=
        std::string::npos);

  std::string b = binary_ply(false);
  std::string e = error_of([&] { ply(b.substr(0, b.size() - 20)); });
  CHECK(e.find("vertex 2 of 3 is cut off") != std::string::npos);
  CHECK(e.find("t.ply: byte ") == 0);
}

TEST_CASE("ply: huge element counts are rejected before allocating", "[ply][errors]") {
  std::string s =
      "ply\nformat binary_little_endian 1.0\nelement face 4000000000\nproperty list uchar int v\n"
      "element vertex 18446744073709551615\nproperty double x\nproperty double y\n"
      "property double z\nend_header\n" +
      std::string(64, '\x01');
  CHECK_THROWS_AS(ply(s), FormatError);
  std::string t =
      "ply\nformat binary_little_endian 1.0\nelement stuff 4000000000\nproperty int a\n"
      "element vertex 1\nproperty double x\nproperty double y\nproperty double z\nend_header\n";
  CHECK(error_of([&] { ply(t); }).find("stuff 0 of 4000000000 is cut off") != std::string::npos);
}

TEST_CASE("ply: non-finite vertices are skipped and counted or rejected", "[ply]") {
  Bytes b;
  b.text(
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nend_header\n");
  b.put<float>(1).put<float>(2).put<float>(3);
  b.put<float>(std::numeric_limits<float>::quiet_NaN()).put<float>(0).put<float>(0);
  b.put<float>(4).put<float>(5).put<float>(6);
  ReadReport report;
  PointCloud c = read_point_cloud_bytes(b.str(), Format::kPly, "t.ply", {}, &report);
  CHECK(c.size() == 2);
  CHECK(report.skipped == 1);
  ReadOptions strict;
  strict.skip_non_finite = false;
  CHECK(error_of([&] { ply(b.str(), strict); }) ==
        "t.ply: byte 127: vertex 1 has a non-finite coordinate");
}

TEST_CASE("ply: truncation at every length gives an error or a valid prefix", "[ply][fuzz]") {
  for (bool big : {false, true}) {
    const std::string full = binary_ply(big);
    for (std::size_t len = 0; len <= full.size(); ++len) {
      std::unique_ptr<char[]> buf(new char[len + 1]);
      std::memcpy(buf.get(), full.data(), len);
      INFO("length " << len);
      try {
        PointCloud c = read_point_cloud_bytes(std::string_view(buf.get(), len), Format::kPly, "t");
        // Only the unneeded trailing edge element may be missing.
        CHECK(c.size() == kVerts.size());
      } catch (const FormatError&) {
      }
    }
  }
  const std::string text = ascii_ply();
  for (std::size_t len = 0; len <= text.size(); ++len) {
    try {
      PointCloud c = ply(text.substr(0, len));
      CHECK(c.size() == kVerts.size());
    } catch (const FormatError&) {
    }
  }
}
