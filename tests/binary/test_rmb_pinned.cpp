// Pins the format (docs/binary-format.md): the primitives, the exact bytes of a tiny grammar in
// version 2, and that version 1 files still decode. A change here is a format change: bump
// kRmbVersion and document it.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>

#include "core/rng.h"
#include "formats/rmb/rmb_codec.h"
#include "rmb_test_util.h"

using namespace ramus;

namespace {

std::string hex(std::string_view s) { return rmb::hex_bytes(s, s.size()); }

ir::Grammar tiny() {
  SourceManager sm;
  DiagnosticSink diags;
  return lower_text("t.ramus", "lsystem t {\n  derive 2;\n  axiom F(1);\n  F(x) -> F(x*2)+F;\n}\n",
                    GrowOptions{}, sm, diags);
}

}  // namespace

TEST_CASE("rmb: primitives of version 1", "[rmb]") {
  rmb::Writer w;
  w.varint(0);
  w.varint(127);
  w.varint(128);
  w.varint(300);
  w.svarint(-1);
  w.svarint(1);
  w.svarint(-64);
  w.f64(1.0);
  w.str("ab");
  w.u16(0x1234);
  w.u32(0xA1B2C3D4u);
  CHECK(hex(w.data()) ==
        "00 7f 80 01 ac 02 01 02 7f 00 00 00 00 00 00 f0 3f 02 61 62 34 12 d4 c3 b2 a1");
  CHECK(rmb::crc32("123456789") == 0xCBF43926u);  // the standard CRC-32 check value
  CHECK(rmb::crc32("") == 0u);

  rmb::Reader r(w.data(), 0, w.size());
  CHECK(r.varint("a") == 0);
  CHECK(r.varint("b") == 127);
  CHECK(r.varint("c") == 128);
  CHECK(r.varint("d") == 300);
  CHECK(r.svarint("e") == -1);
  CHECK(r.svarint("f") == 1);
  CHECK(r.svarint("g") == -64);
  CHECK(r.f64("h") == 1.0);
  CHECK(r.str("i", 10) == "ab");
  CHECK(r.u16("j") == 0x1234);
  CHECK(r.u32("k") == 0xA1B2C3D4u);
  CHECK(r.at_end());
  CHECK_THROWS_AS(r.u8("past the end"), RmbError);
}

TEST_CASE("rmb: overlong and overflowing varints are rejected", "[rmb]") {
  const std::string overlong("\x80\x00", 2);
  rmb::Reader a(overlong, 0, overlong.size());
  CHECK_THROWS_WITH(a.varint("n"), Catch::Contains("overlong"));
  const std::string big("\xff\xff\xff\xff\xff\xff\xff\xff\xff\x02", 10);
  rmb::Reader b(big, 0, big.size());
  CHECK_THROWS_WITH(b.varint("n"), Catch::Contains("overflows"));
  const std::string max("\xff\xff\xff\xff\xff\xff\xff\xff\xff\x01", 10);
  rmb::Reader c(max, 0, max.size());
  CHECK(c.varint("n") == ~std::uint64_t(0));
}

// The hex text back to bytes.
std::string unhex(const char* text) {
  std::string out;
  for (const char* p = text; *p; p += (p[2] == ' ' ? 3 : 2)) {
    out += char(std::stoi(std::string(p, 2), nullptr, 16));
    if (!p[2]) break;
  }
  return out;
}

TEST_CASE("rmb: the bytes of a tiny grammar are pinned", "[rmb]") {
  const std::string bytes = encode_rmb(tiny());
  // Version 2: header, table, nine sections, CRC-32. Reals are decimals (angle 90 is a0 0b:
  // zigzag 180 << 3 | 0 decimals; width_decay 0.707 is b3 58: 707 with 3 decimals), the pool holds
  // 1 and 2 once each, and every code record is implied by its instructions (one byte: length <<
  // 1). 161 bytes.
  const char* kPinned =
      "52 4d 42 1a 02 00 00 00 09 01 26 10 02 36 11 03 47 01 04 48 18 05 60 0d "
      "06 6d 05 07 72 26 08 98 01 04 09 9c 01 01 01 74 00 04 00 a0 0b 10 10 b3 "
      "58 00 00 08 00 10 00 01 01 00 01 01 01 01 01 01 01 01 01 01 01 01 01 00 "
      "03 00 0c 74 2e 72 61 6d 75 73 3a 33 3a 31 31 08 03 34 3a 33 0a 02 31 33 "
      "02 00 10 01 20 04 00 00 01 00 00 00 06 02 02 00 06 02 01 00 00 02 00 00 "
      "00 00 01 01 11 46 28 78 29 20 2d 3e 20 46 28 78 2a 32 29 2b 46 3b 01 00 "
      "03 00 01 02 02 00 00 00 01 00 01 00 00 e5 59 8d c8";
  CHECK(bytes.size() == 161);
  CHECK(hex(bytes) == kPinned);
  CHECK(test::derive_steps(decode_rmb(bytes), 2) == test::derive_steps(tiny(), 2));
}

TEST_CASE("rmb: a version 1 file of a tiny grammar still decodes", "[rmb]") {
  // 256 bytes: header, table, nine sections, CRC-32, as version 1 wrote them.
  const char* kPinned =
      "52 4d 42 1a 01 00 00 00 09 01 2b 46 02 71 11 03 82 01 01 04 83 01 18 05 "
      "9b 01 19 06 b4 01 1d 07 d1 01 26 08 f7 01 04 09 fb 01 01 01 74 00 04 00 "
      "00 00 00 00 00 80 56 40 00 00 00 00 00 00 f0 3f 00 00 00 00 00 00 f0 3f "
      "39 b4 c8 76 be 9f e6 3f 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 "
      "00 00 00 00 00 00 f0 bf 00 00 00 00 00 00 00 00 10 00 01 01 00 01 01 01 "
      "01 01 01 01 01 01 01 01 01 01 00 03 00 0c 74 2e 72 61 6d 75 73 3a 33 3a "
      "31 31 08 03 34 3a 33 0a 02 31 33 02 00 00 00 00 00 00 f0 3f 00 00 00 00 "
      "00 00 00 40 04 00 00 01 00 00 01 06 02 00 01 01 01 00 00 00 00 00 00 f0 "
      "3f 00 00 03 02 03 00 00 00 00 00 00 00 40 00 06 02 01 00 00 02 00 00 00 "
      "00 01 01 11 46 28 78 29 20 2d 3e 20 46 28 78 2a 32 29 2b 46 3b 01 00 03 "
      "00 01 01 02 00 00 00 01 00 01 00 00 93 08 94 fa";
  const std::string bytes = unhex(kPinned);
  CHECK(bytes.size() == 256);
  CHECK(hex(bytes) == kPinned);
  const ir::Grammar g = decode_rmb(bytes);
  CHECK(test::derive_steps(g, 2) == test::derive_steps(tiny(), 2));
  // Re-encoded, it is the version 2 file; asked for version 1, the same bytes again.
  CHECK(encode_rmb(g) == encode_rmb(tiny()));
  RmbEncodeOptions v1;
  v1.version = 1;
  CHECK(hex(encode_rmb(tiny(), v1)) == kPinned);
}

TEST_CASE("rmb: decimal reals of version 2 are exact and as short as their text", "[rmb]") {
  auto bytes_of = [](double v) {
    rmb::Writer w;
    w.decimal();
    w.real(v);
    return w.data();
  };
  CHECK(hex(bytes_of(0)) == "00");
  CHECK(hex(bytes_of(1)) == "10");
  CHECK(hex(bytes_of(-1)) == "08");
  CHECK(hex(bytes_of(0.5)) == "51");                           // 5, one decimal: zigzag 10 << 3 | 1
  CHECK(hex(bytes_of(137.5)) == "f1 ab 01");                   // 1375, one decimal
  CHECK(hex(bytes_of(-0.0)) == "07 00 00 00 00 00 00 00 80");  // no decimal: the f64
  CHECK(hex(bytes_of(1.0 / 3)).substr(0, 3) == "07 ");
  // Exact for any double: random bits, and random short decimals.
  ramus::Rng rng(7);
  for (int i = 0; i < 20000; ++i) {
    double v = 0;
    if (i % 2) {
      const std::uint64_t bits = rng.next_u64();
      std::memcpy(&v, &bits, sizeof v);
    } else {
      v = double(std::int64_t(rng.next_u64() % 2000001) - 1000000) / std::pow(10.0, double(i % 7));
    }
    const std::string b = bytes_of(v);
    rmb::Reader r(b, 0, b.size());
    r.decimal();
    const double back = r.real("v");
    INFO(v);
    CHECK(std::memcmp(&back, &v, sizeof v) == 0);
    CHECK(r.at_end());
    if (i % 2 == 0) CHECK(b.size() <= 4);
  }
  // Not the shortest form: 50 with one decimal instead of 5 with none.
  const std::string longer("\xa1\x06", 2);
  rmb::Reader r(longer, 0, longer.size());
  r.decimal();
  CHECK_THROWS_WITH(r.real("v"), Catch::Contains("shortest form"));
}
