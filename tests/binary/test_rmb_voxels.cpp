// The voxel rule table section (id 11, docs/binary-format.md) of `voxels` blocks: encoded from
// the AST, decoded and verified (counts, class bounds, eight children per rule), dumped, and
// decompiled back to a `voxels` block -- for hand-written blocks and for the block
// `ramus infer --method wavelet` writes from a real scan.
#include <catch2/catch.hpp>

#include "../cli/cli_runner.h"
#include "formats/rmb/rmb_codec.h"
#include "formats/rmb/rmb_decompile.h"
#include "formats/rmb/rmb_voxels.h"
#include "grammar/loader.h"
#include "rejects_damage.h"
#include "rmb_test_util.h"

using namespace ramus;
using namespace cli_test;

namespace {

const char* kSource = R"(const K = 3;
lsystem t {
  derive 2;
  axiom A;
  A -> F[+A]A;
}

voxels oak {
  levels 6;
  classes 16;
  seed 4;
  axiom "oak.axiom.rvx";
  7 -> [0 3 0 7 0 5 0 7] x3;
  K -> [0 1 2 3 4 5 6 15];
}

voxels bare {
  200 -> [255 0 0 0 0 0 0 1] x4000000000;
}
)";

struct Parsed {
  ast::File file;
  ir::Grammar g;
};

Parsed parse(const std::string& text) {
  SourceManager sm;
  DiagnosticSink diags;
  Program p = load_program_text("voxels.ramus", text, sm, diags);
  REQUIRE(!diags.has_errors());
  REQUIRE(!p.files.empty());
  SourceManager sm2;
  DiagnosticSink diags2;
  ir::Grammar g = lower_text("voxels.ramus", text, GrowOptions{}, sm2, diags2);
  REQUIRE(!diags2.has_errors());
  return {std::move(p.files[0]), std::move(g)};
}

bool same_rules(const RmbVoxelTable& a, const RmbVoxelTable& b) {
  if (a.rules.size() != b.rules.size()) return false;
  for (std::size_t i = 0; i < a.rules.size(); ++i) {
    const wavelet::VoxelRule &x = a.rules[i], &y = b.rules[i];
    if (x.parent != y.parent || x.children != y.children || x.count != y.count) return false;
  }
  return a.name == b.name && a.levels == b.levels && a.classes == b.classes && a.seed == b.seed &&
         a.axiom == b.axiom;
}

std::string fix_crc(std::string bytes) {
  const std::uint32_t crc = rmb::crc32(std::string_view(bytes).substr(0, bytes.size() - 4));
  for (int k = 0; k < 4; ++k) bytes[bytes.size() - 4 + k] = char((crc >> (8 * k)) & 0xFF);
  return bytes;
}

}  // namespace

TEST_CASE("binary: voxels blocks round-trip through the voxel rule table section", "[binary]") {
  const Parsed p = parse(kSource);
  const auto tables = voxel_tables_of(p.file, p.g);
  REQUIRE(tables.size() == 2);
  CHECK(tables[0].name == "oak");
  CHECK(tables[0].levels == 6u);
  CHECK(tables[0].classes == 16u);
  CHECK(tables[0].seed == 4u);
  CHECK(tables[0].axiom == std::string("oak.axiom.rvx"));
  REQUIRE(tables[0].rules.size() == 2);
  CHECK(tables[0].rules[1].parent == 3);  // K folded
  CHECK(tables[0].rules[1].count == 0);   // no weight written
  CHECK(tables[1].rules[0].count == 4000000000u);
  CHECK(!tables[1].classes);

  const std::string bytes = encode_rmb(p.g, tables);
  const RmbContents back = decode_rmb_contents(bytes);
  REQUIRE(back.voxels.size() == 2);
  for (std::size_t i = 0; i < 2; ++i) CHECK(same_rules(back.voxels[i], tables[i]));
  CHECK(encode_rmb(back.grammar, back.voxels) == bytes);
  CHECK(test::derive_steps(back.grammar, 2) == test::derive_steps(p.g, 2));
  // Without voxels blocks nothing changes: nine sections, the same bytes as before.
  CHECK(encode_rmb(p.g, std::vector<RmbVoxelTable>{}) == encode_rmb(p.g));
  CHECK(decode_rmb_contents(encode_rmb(p.g)).voxels.empty());

  // Decompiled: the blocks come back, and the text encodes to the same bytes.
  const std::string text = decompile(back);
  INFO(text);
  CHECK(text.find("voxels oak {") != std::string::npos);
  CHECK(text.find("3 -> [0 1 2 3 4 5 6 15];") != std::string::npos);
  CHECK(text.find("200 -> [255 0 0 0 0 0 0 1] x4000000000;") != std::string::npos);
  const Parsed again = parse(text);
  // (Not the same bytes: the text has other locations and no unused `const K`.)
  const auto again_tables = voxel_tables_of(again.file, again.g);
  REQUIRE(again_tables.size() == 2);
  for (std::size_t i = 0; i < 2; ++i) CHECK(same_rules(again_tables[i], tables[i]));
  CHECK(test::derive_steps(again.g, 2) == test::derive_steps(p.g, 2));
}

TEST_CASE("binary: voxel tables combine with stripping, quantization and zstd", "[binary]") {
  const Parsed p = parse(kSource);
  const auto tables = voxel_tables_of(p.file, p.g);
  RmbEncodeOptions o;
  o.strip = true;
  o.zstd = true;
  o.tolerance = 1e-3;
  const RmbContents back = decode_rmb_contents(encode_rmb(p.g, tables, o));
  REQUIRE(back.voxels.size() == 2);
  CHECK(same_rules(back.voxels[0], tables[0]));
  CHECK(same_rules(back.voxels[1], tables[1]));
}

TEST_CASE("binary: what the voxel section cannot carry is an encoding error", "[binary]") {
  const char* bad[] = {
      "lsystem t { axiom A; }\nvoxels v { classes 300; }\n",
      "lsystem t { axiom A; }\nvoxels v { levels 65; }\n",
      "lsystem t { axiom A; }\nvoxels v { 1 -> [0 0 0 0 0 0 0 0] x0.5; }\n",
      "lsystem t { axiom A; }\nvoxels v { 256 -> [0 0 0 0 0 0 0 0]; }\n",
  };
  for (const char* text : bad) {
    INFO(text);
    const Parsed p = parse(text);
    CHECK_THROWS_AS(voxel_tables_of(p.file, p.g), RmbError);
  }
}

TEST_CASE("binary: damaged voxel tables are rejected with the byte offset", "[binary]") {
  const Parsed p = parse(kSource);
  const std::string bytes = encode_rmb(p.g, voxel_tables_of(p.file, p.g));
  test::check_rejects_truncation_and_damage(
      bytes, [](std::string_view b) { return decode_rmb_contents(b); });
  // A class at or above the block's `classes`, behind a valid checksum: the parent of rule 0
  // of block "oak" is the byte after the rule count. Find it through the dump's trace.
  std::vector<rmb::TraceEntry> trace;
  decode_rmb_contents(bytes, {}, &trace);
  std::size_t parent_at = 0;
  for (const rmb::TraceEntry& e : trace) {
    if (e.field == "parent") {
      parent_at = e.offset;
      break;
    }
  }
  REQUIRE(parent_at > 0);
  std::string bad = bytes;
  bad[parent_at] = char(16);
  try {
    decode_rmb_contents(fix_crc(bad));
    FAIL("decoded a class out of range");
  } catch (const RmbError& e) {
    CHECK(e.offset == parent_at);
    CHECK(std::string(e.what()).find("expected a class below 16, found 16") != std::string::npos);
  }
  // Ids from 13 on are not defined; after section 9 only 10 (piece sets), 11 or 12 may follow.
  std::size_t id_at = 0;
  for (const rmb::TraceEntry& e : trace) {
    if (e.field == "section id") id_at = e.offset;  // the last one: 11
  }
  REQUIRE(bytes[id_at] == 11);
  bad = bytes;
  bad[id_at] = 13;
  CHECK_THROWS_WITH(decode_rmb_contents(fix_crc(bad)),
                    Catch::Contains("expected section id 10 (piece sets), 11 (voxel rule tables) "
                                    "or 12 (placed pieces), found 13"));
  // The voxel tables read as piece sets or as placed pieces are rejected inside the section.
  for (char id : {10, 12}) {
    bad[id_at] = id;
    CHECK_THROWS_AS(decode_rmb_contents(fix_crc(bad)), RmbError);
  }
}

TEST_CASE("binary: the voxels block of an inferred wavelet grammar round-trips", "[binary]") {
  TempDir tmp;
  const fs::path src = tmp.path / "wv.ramus", rmb = tmp.path / "wv.rmb",
                 back = tmp.path / "back.ramus", again = tmp.path / "again.rmb";
  REQUIRE(run_ramus({"-q", "infer", std::string(RAMUS_SHARED_DIR) + "/data/plantscan3d_A3B4.asc",
                     "--method", "wavelet", "-o", src.string()})
              .status == 0);
  REQUIRE(
      run_ramus({"-q", "build", src.string(), "--target", "binary", "-o", rmb.string()}).status ==
      0);
  const std::string bytes = slurp(rmb);
  const Parsed p = parse(slurp(src));
  const auto tables = voxel_tables_of(p.file, p.g);
  REQUIRE(tables.size() == 1);
  CHECK(tables[0].rules.size() > 20);
  const RmbContents contents = decode_rmb_contents(bytes);
  REQUIRE(contents.voxels.size() == 1);
  CHECK(same_rules(contents.voxels[0], tables[0]));
  const CliResult dump = run_ramus({"dump", rmb.string()});
  REQUIRE(dump.status == 0);
  CHECK(dump.out.find("-- section 11: voxel rule tables") != std::string::npos);
  REQUIRE(run_ramus({"-q", "decompile", rmb.string(), "-o", back.string()}).status == 0);
  CHECK(run_ramus({"check", back.string()}).status == 0);
  CHECK(run_ramus({"fmt", "--check", back.string()}).status == 0);
  const Parsed q = parse(slurp(back));
  const auto tables2 = voxel_tables_of(q.file, q.g);
  REQUIRE(tables2.size() == 1);
  CHECK(same_rules(tables2[0], tables[0]));
  CHECK(test::derive_steps(q.g, q.g.settings.derive) ==
        test::derive_steps(p.g, p.g.settings.derive));
}

TEST_CASE("binary: the dump of a stripped file with voxel tables matches its golden file",
          "[binary]") {
  const Parsed p = parse(kSource);
  RmbEncodeOptions o;
  o.strip = true;
  const std::string bytes = encode_rmb(p.g, voxel_tables_of(p.file, p.g), o);
  std::vector<rmb::TraceEntry> trace;
  decode_rmb_contents(bytes, {}, &trace);
  const std::string actual =
      format_rmb_trace(bytes, trace) + std::to_string(bytes.size()) + " bytes\n";
  const fs::path golden = fs::path(RAMUS_SOURCE_DIR) / "tests/golden/rmb/voxels_stripped.rmb.txt";
  INFO("golden file: " << golden.string());
  if (std::getenv("RAMUS_UPDATE_GOLDENS")) write_text(golden, actual);
  CHECK(slurp(golden) == actual);
}
