// Pins format version 1 (docs/binary-format.md): the primitives, and the exact bytes of a tiny
// grammar. A change here is a format change: bump kRmbVersion and document it.
#include <catch2/catch.hpp>

#include "compiler/rmb_codec.h"
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

TEST_CASE("rmb: the bytes of a tiny grammar are pinned", "[rmb]") {
  const std::string bytes = encode_rmb(tiny());
  // 256 bytes: header, table, nine sections, CRC-32.
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
  CHECK(bytes.size() == 256);
  CHECK(hex(bytes) == kPinned);
  CHECK(test::derive_steps(decode_rmb(bytes), 2) == test::derive_steps(tiny(), 2));
}
