// A truncated or corrupted .rmb is rejected with an RmbError naming the byte offset, never a
// crash: truncation at every length, each byte flipped at every offset, and -- behind a
// checksum switched off -- structural damage the decoder must catch by itself.
#include <catch2/catch.hpp>
#include <fstream>
#include <iterator>

#include "compiler/expr_vm.h"
#include "formats/rmb/rmb_codec.h"
#include "rmb_test_util.h"

using namespace ramus;

namespace {

const char* kFiles[] = {"examples/abop/fig1_24a.ramus", "examples/abop/param_p42.ramus",
                        "examples/trees/weeping.ramus"};

// Decodes `bytes`; if accepted, derives a little with small limits. Returns true on RmbError.
bool rejected_or_harmless(std::string_view bytes, const RmbDecodeOptions& o) {
  ir::Grammar g;
  try {
    g = decode_rmb(bytes, o);
  } catch (const RmbError& e) {
    CHECK(e.offset <= bytes.size());
    return true;
  }
  try {
    test::derive_steps(g, std::min(g.settings.derive, 3), 20'000);
  } catch (const DeriveError&) {
  } catch (const ExprError&) {
  }
  return false;
}

}  // namespace

TEST_CASE("rmb: truncation at every length is rejected", "[rmb]") {
  for (const char* file : kFiles) {
    INFO(file);
    const std::string bytes = encode_rmb(test::lower_example(file));
    for (std::size_t n = 0; n < bytes.size(); ++n) {
      INFO("length " << n);
      CHECK_THROWS_AS(decode_rmb(std::string_view(bytes).substr(0, n)), RmbError);
    }
  }
}

TEST_CASE("rmb: a flipped byte at every offset is rejected", "[rmb]") {
  for (const char* file : kFiles) {
    INFO(file);
    const std::string good = encode_rmb(test::lower_example(file));
    for (std::size_t i = 0; i < good.size(); ++i) {
      for (unsigned char mask : {0x01, 0x80, 0xFF}) {
        std::string bad = good;
        bad[i] = char(bad[i] ^ mask);
        INFO("offset " << i << " mask " << int(mask));
        CHECK_THROWS_AS(decode_rmb(bad), RmbError);
      }
    }
  }
}

TEST_CASE("rmb: structural damage behind a disabled checksum never crashes", "[rmb]") {
  RmbDecodeOptions unchecked;
  unchecked.verify_checksum = false;
  std::size_t rejected = 0, total = 0;
  for (const char* file : kFiles) {
    INFO(file);
    const std::string good = encode_rmb(test::lower_example(file));
    REQUIRE_FALSE(rejected_or_harmless(good, unchecked));
    for (std::size_t n = 0; n < good.size(); ++n) {
      INFO("length " << n);
      CHECK(rejected_or_harmless(std::string_view(good).substr(0, n), unchecked));
    }
    for (std::size_t i = 0; i + 4 < good.size(); ++i) {
      for (unsigned char value : {0x00, 0x01, 0x7F, 0x80, 0xFF}) {
        if (std::uint8_t(good[i]) == value) continue;
        std::string bad = good;
        bad[i] = char(value);
        INFO("offset " << i << " value " << int(value));
        rejected += rejected_or_harmless(bad, unchecked);
        ++total;
      }
    }
  }
  // Damage inside doubles and strings (most of these files) is still a valid file; damage to
  // ids, counts, ranges and varints must be caught without the CRC (15% of all cases here).
  CHECK(rejected * 10 > total);
}

TEST_CASE("rmb: errors name the offset and what was expected", "[rmb]") {
  const std::string good = encode_rmb(test::lower_example("examples/abop/fig1_24a.ramus"));
  std::string bad = good;
  bad[0] = 'X';
  try {
    decode_rmb(bad);
    FAIL("accepted a bad magic");
  } catch (const RmbError& e) {
    CHECK(e.offset == 0);
    CHECK(std::string(e.what()).find("magic") != std::string::npos);
  }
  bad = good;
  bad[10] = char(bad[10] ^ 0x10);
  try {
    decode_rmb(bad);
    FAIL("accepted a bad checksum");
  } catch (const RmbError& e) {
    CHECK(e.offset == good.size() - 4);
    CHECK(std::string(e.what()).find("CRC-32") != std::string::npos);
  }
  try {
    decode_rmb(std::string_view(good).substr(0, 20));
    FAIL("accepted a truncated file");
  } catch (const RmbError& e) {
    CHECK(std::string(e.what()).find("byte ") == 0);
  }
  bad = good;
  bad[4] = 3;  // version 3
  CHECK_THROWS_WITH(decode_rmb(bad), Catch::Contains("expected format version 1 or 2, found 3"));
}

TEST_CASE("rmb: a production without an alternative is refused at decoding", "[rmb]") {
  // Found by fuzz_decode_rmb: the derivation's stochastic choice read the production's first
  // alternative, past the end of the table.
  std::ifstream in(std::string(RAMUS_SOURCE_DIR) +
                       "/tests/fuzz/corpus/decode_rmb/regress_production_without_alternative.rmb",
                   std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  REQUIRE(bytes.size() == 319);
  try {
    decode_rmb(bytes);
    FAIL("accepted a production without an alternative");
  } catch (const RmbError& e) {
    CHECK(e.offset == 290);
    CHECK(std::string(e.what()) == "byte 290: expected at least one alternative");
  }
}
