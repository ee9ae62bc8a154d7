// Malformed LAZ: every damage gets a FormatError naming the file and the byte offset, never a
// crash or a hang: truncation at every length, a bad chunk table offset, point counts that
// disagree, broken laszip VLRs, corrupt chunk bytes.
#include <catch2/catch.hpp>
#include <cstring>

#include "core/rng.h"
#include "format_test_util.h"
#include "formats/las_file.h"
#include "formats/point_cloud_io.h"

using namespace ramus;

namespace {

// A small LAZ file: point format 1, 250 points in chunks of 100.
std::string small_laz() {
  test::LasSpec spec;
  spec.format = 1;
  std::vector<test::LasPoint> pts;
  Rng rng(5);
  for (int i = 0; i < 250; ++i) {
    const auto u = rng.next_u64();
    pts.push_back({i * 37 + std::int32_t(u % 50), std::int32_t(u >> 8) % 1000, i % 97,
                   std::uint16_t(u % 300), std::uint8_t(i % 3 == 0 ? 2 : 5)});
  }
  std::string las = test::make_las(spec, pts);
  for (int i = 0; i < 250; ++i) {
    const double t = 1000 + i * 0.001;
    std::memcpy(las.data() + 227 + 28 * i + 20, &t, 8);
  }
  return compress_las(las, "small.las", 100);
}

std::string error_of(const std::string& bytes) {
  try {
    read_point_cloud_bytes(bytes, Format::kLas, "bad.laz");
  } catch (const FormatError& e) {
    return e.what();
  }
  return "";
}

std::uint32_t point_offset(const std::string& laz) {
  std::uint32_t v;
  std::memcpy(&v, laz.data() + 96, 4);
  return v;
}

}  // namespace

TEST_CASE("laz errors: truncation at every length is an error with a byte offset",
          "[laz][errors][fuzz]") {
  const std::string laz = small_laz();
  REQUIRE(read_point_cloud_bytes(laz, Format::kLas, "ok.laz").size() == 250);
  for (std::size_t n = 0; n < laz.size(); ++n) {
    const std::string e = error_of(laz.substr(0, n));
    INFO("cut at " << n << ": " << e);
    REQUIRE(!e.empty());
    CHECK(e.rfind("bad.laz", 0) == 0);
    if (n >= 4) CHECK(e.find(": byte ") != std::string::npos);
  }
}

TEST_CASE("laz errors: a bad chunk table offset or a cut chunk names its byte", "[laz][errors]") {
  const std::string laz = small_laz();
  const std::uint32_t at = point_offset(laz);
  std::string s = laz;
  test::poke<std::int64_t>(s, at, std::int64_t(s.size()) + 100);
  CHECK(error_of(s).find("bad.laz: byte " + std::to_string(at) + ": the chunk table offset " +
                         std::to_string(laz.size() + 100) + " is outside the compressed points") ==
        0);
  test::poke<std::int64_t>(s, at, 12);
  CHECK(error_of(s).find("bad.laz: byte " + std::to_string(at) + ": the chunk table offset 12") ==
        0);

  // The chunk table moved 40 bytes earlier: chunk 3's bytes now run into it.
  std::int64_t table;
  std::memcpy(&table, laz.data() + at, 8);
  s = laz.substr(0, std::size_t(table) - 40) + laz.substr(std::size_t(table));
  test::poke<std::int64_t>(s, at, table - 40);
  CHECK(error_of(s).find("runs past the chunk table at byte " + std::to_string(table - 40)) !=
        std::string::npos);
}

TEST_CASE("laz errors: point counts that disagree with the chunk table", "[laz][errors]") {
  const std::string laz = small_laz();
  std::string s = laz;
  test::poke<std::uint32_t>(s, 107, 400);  // 4 chunks of 100 expected, the table has 3
  std::int64_t table;
  std::memcpy(&table, laz.data() + point_offset(laz), 8);
  CHECK(error_of(s) == "bad.laz: byte " + std::to_string(table + 4) +
                           ": the chunk table lists 3 chunks but the header's 400 points in "
                           "chunks of 100 make 4");
  test::poke<std::uint32_t>(s, 107, 120);  // 2 chunks expected
  CHECK(error_of(s).find("lists 3 chunks but the header's 120 points") != std::string::npos);
  test::poke<std::uint32_t>(s, 107, 260);  // 3 chunks, but the last lacks 10 points' bytes
  CHECK(error_of(s).find("ends after") != std::string::npos);
}

TEST_CASE("laz errors: a count no chunk could hold is refused before decoding", "[laz][errors]") {
  std::string s = small_laz();
  const std::size_t payload = s.find("laszip encoded") - 2 + 54;
  test::poke<std::uint32_t>(s, payload + 12, 4000000);  // chunks of 4 million points
  test::poke<std::uint32_t>(s, 107, 10000000);          // three chunks' worth
  const std::string e = error_of(s);
  INFO(e);
  CHECK(e.find("bad.laz: byte " + std::to_string(point_offset(s) + 8) +
               ": chunk 1 of 3 would hold 4000000 points in ") == 0);
  CHECK(e.find("the point count or the chunk table is corrupt") != std::string::npos);
}

TEST_CASE("laz errors: broken laszip VLRs", "[laz][errors]") {
  const std::string laz = small_laz();
  const std::size_t payload = laz.find("laszip encoded") - 2 + 54;
  std::string s = laz;
  test::poke<std::uint16_t>(s, payload, 7);
  CHECK(error_of(s) == "bad.laz: byte " + std::to_string(payload) +
                           ": unknown LAZ compressor 7 (expected 1 pointwise, 2 chunked or 3 "
                           "layered chunked)");
  s = laz;
  test::poke<std::uint16_t>(s, payload + 2, 1);
  CHECK(error_of(s).find("unknown LAZ entropy coder 1") != std::string::npos);
  s = laz;
  test::poke<std::uint16_t>(s, payload + 32, 40);  // 40 items do not fit the record
  CHECK(error_of(s) == "bad.laz: byte " + std::to_string(payload + 32) +
                           ": the laszip record lists 40 items (274 bytes) but has 46 bytes");
  s = laz;
  test::poke<std::uint16_t>(s, payload + 34 + 4, 1);  // point10 version 1
  CHECK(error_of(s).find("LAZ item point10 v1 (20 bytes) is not supported") != std::string::npos);
  s = laz;
  test::poke<std::uint16_t>(s, payload + 34 + 6 + 2, 9);  // gpstime11 of 9 bytes
  CHECK(error_of(s).find("the laszip record's items add up to 29-byte records but the header "
                         "says 28") != std::string::npos);
  s = laz;
  s[104] = 1;  // no compression bit, but the VLR: still LAZ, still reads
  CHECK(read_point_cloud_bytes(s, Format::kLas, "t.laz").size() == 250);
}

TEST_CASE("laz errors: corrupt chunk bytes never crash", "[laz][errors][fuzz]") {
  const std::string laz = small_laz();
  const std::size_t start = point_offset(laz) + 8;
  Rng rng(11);
  for (std::size_t i = start; i < laz.size(); ++i) {
    std::string s = laz;
    s[i] = char(s[i] ^ (1 + rng.next_u64() % 255));
    try {
      PointCloud c = read_point_cloud_bytes(s, Format::kLas, "bad.laz");
      CHECK(c.size() == 250);  // garbage values maybe, but the promised count
    } catch (const FormatError& e) {
      CHECK(std::string(e.what()).find("bad.laz: byte ") == 0);
    }
  }
}

TEST_CASE("laz errors: a layered file (format 7, extra bytes) cut or corrupted never crashes",
          "[laz][errors][fuzz][layered]") {
  test::LasSpec spec;
  spec.minor = 4;
  spec.format = 7;
  spec.extra_bytes = 2;
  std::vector<test::LasPoint> pts;
  Rng rng(8);
  for (int i = 0; i < 180; ++i) {
    const auto u = rng.next_u64();
    pts.push_back({i * 51 + std::int32_t(u % 40), std::int32_t(u >> 9) % 800, i % 61,
                   std::uint16_t(u % 500), std::uint8_t(40 + i % 3)});
  }
  std::string las = test::make_las(spec, pts);
  for (int i = 0; i < 180; ++i) {  // colours, times, a second scanner channel now and then
    char* r = las.data() + 375 + 38 * i;
    const double t = 5e5 + i * 1e-4;
    std::memcpy(r + 22, &t, 8);
    r[15] = char(i % 17 == 0 ? 0x10 : 0);
    const std::uint16_t rgb[3] = {std::uint16_t(i * 300), std::uint16_t(i * 301), 7};
    std::memcpy(r + 30, rgb, 6);
  }
  const std::string laz = compress_las(las, "small.las", 64);
  REQUIRE(decompress_laz(laz, "ok.laz") == las);
  for (std::size_t n = 0; n < laz.size(); ++n) {
    const std::string e = error_of(laz.substr(0, n));
    INFO("cut at " << n << ": " << e);
    REQUIRE(!e.empty());
  }
  const std::size_t start = point_offset(laz) + 8;
  for (std::size_t i = start; i < laz.size(); ++i) {
    std::string s = laz;
    s[i] = char(s[i] ^ (1 + rng.next_u64() % 255));
    try {
      const PointCloud c = read_point_cloud_bytes(s, Format::kLas, "bad.laz");
      CHECK(c.size() == 180);
    } catch (const FormatError& e) {
      CHECK(std::string(e.what()).find("bad.laz: byte ") == 0);
    }
  }
}
