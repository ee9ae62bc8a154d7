// Stripped .rmb files (flag bit 2, `ramus build --target binary --strip`, docs/binary-format.md):
// no source locations and no production texts. For every example the stripped file derives the
// same string as the source for the same seed, is smaller, re-encodes to the same bytes,
// decompiles to text that derives the same, and is rejected when truncated; errors at derivation
// time name the production by its index.
#include <catch2/catch.hpp>

#include "../cli/cli_runner.h"
#include "formats/rmb/rmb_codec.h"
#include "formats/rmb/rmb_decompile.h"
#include "rejects_damage.h"
#include "rmb_test_util.h"

using namespace ramus;
using namespace cli_test;

namespace {

RmbEncodeOptions stripped() {
  RmbEncodeOptions o;
  o.strip = true;
  return o;
}

ir::Grammar relower(const std::string& text) {
  SourceManager sm;
  DiagnosticSink diags;
  ir::Grammar g = lower_text("decompiled.ramus", text, GrowOptions{}, sm, diags);
  REQUIRE(!diags.has_errors());
  return g;
}

}  // namespace

TEST_CASE("binary: every example round-trips stripped with identical derivations", "[binary]") {
  const auto files = test::example_grammars();
  REQUIRE(files.size() >= 20);
  for (const std::string& file : files) {
    INFO(file);
    const ir::Grammar g = test::lower_example(file);
    const std::string plain = encode_rmb(g);
    const std::string bytes = encode_rmb(g, stripped());
    CHECK(std::uint8_t(bytes[6]) == kRmbStripped);
    // What is left out: at least every production text and a location byte per production.
    std::size_t debug = 0;
    for (const ir::Production& p : g.productions) debug += p.text.size() + 1;
    CHECK(bytes.size() + debug < plain.size());
    const ir::Grammar back = decode_rmb(bytes);
    CHECK(encode_rmb(back, stripped()) == bytes);
    REQUIRE(back.productions.size() == g.productions.size());
    REQUIRE(back.locations.size() == g.productions.size() + 1);
    for (std::size_t i = 0; i < back.productions.size(); ++i) {
      CHECK(back.locations[back.productions[i].where] == "production " + std::to_string(i));
      CHECK(back.productions[i].text == "#" + std::to_string(i));
    }
    for (const ir::Code& c : back.codes) CHECK(c.where < back.locations.size());
    const ModuleString a = test::derive_steps(g, g.settings.derive);
    CHECK(a.size() > 0);
    CHECK(a == test::derive_steps(back, back.settings.derive));
    // Decompiled: formal parameters by slot (p0, p1, ...), and the same derivation.
    const std::string text = decompile(back);
    INFO(text);
    const ir::Grammar again = relower(text);
    CHECK(a == test::derive_steps(again, again.settings.derive));
  }
}

TEST_CASE("binary: a stripped stochastic grammar derives the same for other seeds", "[binary]") {
  const ir::Grammar g = test::lower_example("examples/trees/broadleaf.ramus");
  const ir::Grammar back = decode_rmb(encode_rmb(g, stripped()));
  for (std::uint64_t seed : {1ull, 99ull, 123456789ull}) {
    CHECK(test::derive_with_seed(g, seed) == test::derive_with_seed(back, seed));
  }
}

TEST_CASE("binary: stripping combines with quantization and zstd", "[binary]") {
  const ir::Grammar g = test::lower_example("examples/trees/conifer.ramus");
  RmbEncodeOptions o = stripped();
  o.zstd = true;
  const std::string z = encode_rmb(g, o);
  CHECK(std::uint8_t(z[6]) == (kRmbStripped | kRmbZstd));
  const ir::Grammar zback = decode_rmb(z);
  CHECK(encode_rmb(zback, stripped()) == encode_rmb(g, stripped()));
  o.zstd = false;
  o.tolerance = 1e-3;
  const std::string q = encode_rmb(g, o);
  CHECK(std::uint8_t(q[6]) == (kRmbStripped | kRmbQuantized));
  CHECK(encode_rmb(decode_rmb(q), o) == q);
  // Version 2 already stores hand-written numbers as short decimals: quantizing them gains
  // nothing and adds the exponent, so the file stays within 1% of the exact one.
  const std::size_t exact = encode_rmb(g, stripped()).size();
  CHECK(q.size() <= exact + exact / 100 + 1);
}

TEST_CASE("binary: a truncated or damaged stripped file is rejected", "[binary]") {
  const ir::Grammar g = test::lower_example("examples/abop/fig1_25.ramus");
  const std::string bytes = encode_rmb(g, stripped());
  test::check_rejects_truncation_and_damage(bytes,
                                            [](std::string_view b) { return decode_rmb(b); });
}

TEST_CASE("binary: a stripped file may not hold locations", "[binary]") {
  // Flag bit 2 set on a file that still has its locations: the count must be 0.
  const ir::Grammar g = test::lower_example("examples/abop/fig1_24a.ramus");
  std::string bytes = encode_rmb(g);
  bytes[6] = char(kRmbStripped);
  const std::uint32_t crc = rmb::crc32(std::string_view(bytes).substr(0, bytes.size() - 4));
  for (int k = 0; k < 4; ++k) bytes[bytes.size() - 4 + k] = char((crc >> (8 * k)) & 0xFF);
  try {
    decode_rmb(bytes);
    FAIL("decoded a stripped file with locations");
  } catch (const RmbError& e) {
    CHECK(std::string(e.what()).find("locations") != std::string::npos);
  }
}

TEST_CASE("binary: errors of a stripped grammar name the production by index", "[binary]") {
  const std::string source = R"(lsystem neg {
  derive 3;
  axiom A(1);
  B -> F;
  A(x) -> (x - 2) F A(x) | (1) F;
}
)";
  const ir::Grammar g = relower(source);
  const ir::Grammar back = decode_rmb(encode_rmb(g, stripped()));
  try {
    test::derive_steps(back, 3);
    FAIL("a negative probability derived");
  } catch (const std::exception& e) {
    const std::string what = e.what();
    INFO(what);
    CHECK(what.find("negative probability") != std::string::npos);
    CHECK(what.find("production 1") != std::string::npos);
    CHECK(what.find("decompiled.ramus") == std::string::npos);
  }
}

TEST_CASE("binary: ramus build --strip, dump and decompile", "[binary]") {
  TempDir tmp;
  const std::string src = std::string(RAMUS_SOURCE_DIR) + "/examples/abop/fig2_6a_monopodial.ramus";
  const fs::path plain = tmp.path / "plain.rmb", small = tmp.path / "small.rmb";
  REQUIRE(run_ramus({"-q", "build", src, "--target", "binary", "-o", plain.string()}).status == 0);
  REQUIRE(run_ramus({"-q", "build", src, "--target", "binary", "--strip", "-o", small.string()})
              .status == 0);
  CHECK(fs::file_size(small) < fs::file_size(plain));
  const CliResult dump = run_ramus({"dump", small.string()});
  REQUIRE(dump.status == 0);
  CHECK(dump.out.find("flags                   4") != std::string::npos);
  CHECK(dump.out.find("  text  ") == std::string::npos);
  CHECK(dump.out.find("  where  ") == std::string::npos);
  const fs::path out = tmp.path / "back.ramus";
  REQUIRE(run_ramus({"-q", "decompile", small.string(), "-o", out.string()}).status == 0);
  CHECK(slurp(out).find("(p0") != std::string::npos);
  CHECK(run_ramus({"check", out.string()}).status == 0);
  CHECK(run_ramus({"fmt", "--check", out.string()}).status == 0);
}
