// The placed-pieces section (id 12, docs/binary-format.md): a stream with every joint mode
// round-trips through the section codec and whole .rmb files (plain, zstd, beside other
// sections); its rotations dequantize within the stated tolerance; a malformed stream is an
// RmbError at the offending byte with what was expected there, never a crash, whatever byte is
// cut or changed; the decompiler says what it leaves out.
#include <catch2/catch.hpp>
#include <cmath>

#include "../cli/cli_runner.h"
#include "formats/rmb/rmb_codec.h"
#include "formats/rmb/rmb_decompile.h"
#include "formats/rmb/rmb_piece_stream_expand.h"
#include "rejects_damage.h"

using namespace ramus;

namespace {

// Two types (a tube, a fork), two trees: the first at rest, the second with a turned joint and
// a moved one.
RmbPieceStream sample_stream() {
  RmbPieceStream s;
  s.set = "grove";
  s.tiles_per_type = {3, 2};
  for (int k = 0; k < kRmbTwists; ++k) s.twists[k] = Quat::axis_angle({0, 0, 1}, M_PI / 3 * k);
  RmbStreamType tube{"I", {Trs{{0, 0, 4}, {}, 0.9}}, {1, 1, 1, 1, 1, 1, 2, 1, 1}};
  RmbStreamType fork{"Y",
                     {Trs{{-1, 0, 3}, Quat::axis_angle({0, 1, 0}, -0.5), 0.8},
                      Trs{{1, 0, 3}, Quat::axis_angle({0, 1, 0}, 0.5), 0.8}},
                     {2, 2, 1}};
  s.types = {tube, fork};
  RmbPlacedTree rest;
  rest.placement = Trs{{1, 2, 0}, {}, 0.3};
  rest.tile_seed = 42;
  rest.pieces = {{0, kRmbNoParent, 0, 0, {}}, {1, 0, 0, 3, {}}, {0, 1, 1, 5, {}}, {0, 1, 0, 1, {}}};
  RmbPlacedTree posed = rest;
  posed.tile_seed = 43;
  RmbJointPose turned;
  turned.mode = RmbJointMode::Turned;
  turned.rotation = rmb_quantize_rotation(Quat::axis_angle({1, 0.2, 0}, 0.1));
  RmbJointPose moved;
  moved.mode = RmbJointMode::Moved;
  moved.rotation = rmb_quantize_rotation(Quat::axis_angle({0.3, -1, 0.5}, 2.5));
  moved.t = {0.5f, -0.25f, 3.75f};
  moved.s = 0.7f;
  posed.pieces[1].joints = {RmbJointPose{}, turned, moved};
  s.trees = {rest, posed};
  return s;
}

std::string section_bytes(const RmbPieceStream& s) {
  rmb::Writer w;
  write_rmb_piece_stream(w, s);
  return w.data();
}

RmbPieceStream read_section(std::string_view bytes) {
  rmb::Reader r(bytes, 0, bytes.size());
  RmbPieceStream s = read_rmb_piece_stream(r);
  if (!r.at_end()) r.fail("expected the end of the section");
  return s;
}

std::string error_of(std::string_view bytes) {
  try {
    read_section(bytes);
  } catch (const RmbError& e) {
    return e.what();
  }
  return "";
}

// The offset of the first piece record of tree 0 (after the placement, seed and count).
std::size_t first_piece_at(const RmbPieceStream& s) {
  RmbPieceStream header = s;
  header.trees.clear();
  return section_bytes(header).size() + 64 + 1 + 1;
}

}  // namespace

TEST_CASE("a placed-pieces stream round-trips through its section and whole .rmb files",
          "[binary][pieces]") {
  const RmbPieceStream s = sample_stream();
  REQUIRE(read_section(section_bytes(s)) == s);
  for (bool zstd : {false, true}) {
    RmbEncodeOptions o;
    o.zstd = zstd;
    const std::string file = encode_rmb(ir::make_grammar(""), {}, {}, s, o);
    const RmbContents c = decode_rmb_contents(file);
    REQUIRE(c.placed == s);
    REQUIRE(c.pieces.empty());
    // Re-encoding what was decoded gives the same bytes.
    REQUIRE(encode_rmb(c.grammar, c.voxels, c.pieces, c.placed, o) == file);
  }
  // A file without the section decodes to an empty stream.
  REQUIRE(decode_rmb_contents(encode_rmb(ir::make_grammar(""))).placed.empty());
  // `ramus dump` names the section and the joint modes.
  std::vector<rmb::TraceEntry> trace;
  const std::string file = encode_rmb(ir::make_grammar(""), {}, {}, s);
  decode_rmb_contents(file, {}, &trace);
  const std::string listing = format_rmb_trace(file, trace);
  REQUIRE(listing.find("section 12: placed pieces") != std::string::npos);
  REQUIRE(listing.find("(turned)") != std::string::npos);
  REQUIRE(listing.find("(moved)") != std::string::npos);
}

TEST_CASE("quantized rotations come back within the stated tolerance", "[binary][pieces]") {
  // Each stored component within 2^-17 of the unit quaternion's, so the three are within
  // sqrt(3) * 2^-17 and the recomputed largest within as much again: the two unit quaternions
  // are within sqrt(2) * sqrt(3) * 2^-17 of each other, the rotations within twice that,
  // 3.7e-5 radians, whatever the rotation.
  double worst = 0;
  for (int i = 0; i < 2000; ++i) {
    const double a = 0.37 * i, b = 0.11 * i + 1;
    const Vec3 axis{std::cos(a) * std::sin(b), std::sin(a) * std::sin(b), std::cos(b)};
    const Quat q = Quat::axis_angle(axis, std::fmod(0.013 * i * i, 2 * M_PI) - M_PI);
    const Quat back = rmb_rotation(rmb_quantize_rotation(q));
    const double dot = std::abs(q.w * back.w + q.x * back.x + q.y * back.y + q.z * back.z);
    const double norm =
        std::sqrt(back.w * back.w + back.x * back.x + back.y * back.y + back.z * back.z);
    worst = std::max(worst, 2 * std::acos(std::min(1.0, dot / norm)));
  }
  REQUIRE(worst < 4e-5);
  REQUIRE(worst > 1e-6);  // quantized, not exact
  // Quantizing a dequantized rotation changes nothing: stored poses are fixed points.
  const RmbRotation r = rmb_quantize_rotation(Quat::axis_angle({1, 2, 3}, 1.0));
  REQUIRE(rmb_quantize_rotation(rmb_rotation(r)) == r);
}

TEST_CASE("a malformed placed-pieces stream is an RmbError at its byte, never a crash",
          "[binary][pieces]") {
  const RmbPieceStream s = sample_stream();
  const std::string bytes = section_bytes(s);
  // Every cut and every changed byte: an error, or a stream that verifies and expands.
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    INFO(n);
    CHECK_THROWS_AS(read_section(std::string_view(bytes).substr(0, n)), RmbError);
  }
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    for (int flip : {0x01, 0x40, 0x7f, 0xff}) {
      std::string bad = bytes;
      bad[i] = char(bad[i] ^ flip);
      try {
        const RmbPieceStream got = read_section(bad);
        CHECK_NOTHROW(expand_piece_stream(got));
      } catch (const RmbError& e) {
        CHECK(std::string(e.what()).find("expected") != std::string::npos);
      }
    }
  }
  // Particular faults, each named with its offset.
  const std::size_t at = first_piece_at(s);
  std::string bad = bytes;
  bad[at] = char(2 << 1);  // piece type 2 of 2
  REQUIRE(error_of(bad) == "byte " + std::to_string(at) + ": expected a piece type < 2, found 2");
  bad = bytes;
  bad[at + 2] = 0;  // piece 1's parent 0 pieces back
  REQUIRE(error_of(bad) ==
          "byte " + std::to_string(at + 2) + ": expected a parent 1..1 pieces back, found 0");
  bad = bytes;
  bad[at + 3] = char(1 * kRmbTwists);  // leaf rim 1 of a tube
  REQUIRE(error_of(bad) ==
          "byte " + std::to_string(at + 3) + ": expected a leaf rim < 1 of I, found 1");
  // The placement's scale (the last f64 before the seed): 0 is not a similarity.
  RmbPieceStream header = s;
  header.trees.clear();
  const std::size_t placement = section_bytes(header).size();
  bad = bytes;
  for (int b = 0; b < 8; ++b) bad[placement + 56 + b] = 0;
  REQUIRE(error_of(bad) == "byte " + std::to_string(placement) +
                               ": expected a tree placement: finite, with a scale > 0");
  // A joint mode byte of 3 in the posed tree (tree 1, piece 1, its first joint).
  const std::string tree0 = [&] {
    RmbPieceStream one = s;
    one.trees.resize(1);
    return section_bytes(one);
  }();
  const std::size_t tree1 = tree0.size();  // tree 1 starts where a one-tree section ends
  // Placement, seed, count, the root piece's head, piece 1's head, back and rim: its first joint.
  const std::size_t mode_at = tree1 + 64 + 1 + 1 + 1 + 1 + 1 + 1;
  REQUIRE(std::uint8_t(bytes[mode_at]) == 0);
  bad = bytes;
  bad[mode_at] = 3;
  REQUIRE(error_of(bad).rfind("byte " + std::to_string(mode_at) + ": expected a joint mode", 0) ==
          0);
}

TEST_CASE("the stream section is verified inside a whole file", "[binary][pieces]") {
  const std::string file = encode_rmb(ir::make_grammar(""), {}, {}, sample_stream());
  ramus::test::check_rejects_truncation_and_damage(
      file, [](std::string_view b) { return decode_rmb_contents(b); });
  // Behind the checksum: a piece type out of range is reported at its offset in the file.
  RmbDecodeOptions unchecked;
  unchecked.verify_checksum = false;
  const std::size_t section_at = file.size() - 4 - section_bytes(sample_stream()).size();
  std::string bad = file;
  const std::size_t at = section_at + first_piece_at(sample_stream());
  bad[at] = char(9 << 1);
  try {
    decode_rmb_contents(bad, unchecked);
    FAIL("decoded");
  } catch (const RmbError& e) {
    REQUIRE(std::string(e.what()) ==
            "byte " + std::to_string(at) + ": expected a piece type < 2, found 9");
  }
}

TEST_CASE("decompiling an .rmb with placed pieces says they are left out", "[binary][pieces]") {
  RmbContents c;
  c.grammar = ir::make_grammar("");
  REQUIRE(decompile_left_out(c).empty());
  c.placed = sample_stream();
  REQUIRE(decompile_left_out(c) ==
          "the placed pieces (section 12: 2 tree(s), 8 pieces of set 'grove') are a built tree, "
          "not grammar text; `ramus build --target binary --placed-pieces` stores them again");
}

TEST_CASE("ramus build --placed-pieces: options, .rmb inputs, dump and decompile",
          "[binary][pieces][cli]") {
  using namespace cli_test;
  TempDir dir;
  const std::string almond = std::string(RAMUS_SOURCE_DIR) + "/examples/pieces/almond.ramus";
  const std::string rmb = (dir.path / "a.rmb").string();
  // --pieces and --poses choose the placed tree, so without --placed-pieces they are mistakes.
  CliResult r = run_ramus({"build", almond, "--target", "binary", "--poses", "3", "-o", rmb});
  REQUIRE(r.status == 1);
  REQUIRE(r.out.find("--poses with --target binary needs --placed-pieces") != std::string::npos);
  r = run_ramus({"build", almond, "--target", "pieces", "--placed-pieces", "-o",
                 (dir.path / "a.glb").string()});
  REQUIRE(r.status == 1);
  REQUIRE(r.out.find("--placed-pieces applies to --target binary only") != std::string::npos);
  r = run_ramus({"build", std::string(RAMUS_SOURCE_DIR) + "/examples/abop/fig1_24a.ramus",
                 "--target", "binary", "--placed-pieces", "-o", rmb});
  REQUIRE(r.status == 1);
  REQUIRE(r.out.find("no pieces block") != std::string::npos);
  // Built, rebuilt from the .rmb (kept as it is, or placed again from its own piece set with
  // the same arguments: the same stream), compressed.
  REQUIRE(run_ramus(
              {"build", almond, "--target", "binary", "--placed-pieces", "--poses", "2", "-o", rmb})
              .status == 0);
  const RmbContents built = decode_rmb_contents(slurp(rmb));
  REQUIRE(built.placed.trees.size() == 2);
  const std::string kept = (dir.path / "kept.rmb").string();
  const std::string again = (dir.path / "again.rmb").string();
  const std::string zstd = (dir.path / "z.rmb").string();
  REQUIRE(run_ramus({"build", rmb, "--target", "binary", "-o", kept}).status == 0);
  REQUIRE(run_ramus(
              {"build", rmb, "--target", "binary", "--placed-pieces", "--poses", "2", "-o", again})
              .status == 0);
  REQUIRE(run_ramus({"build", rmb, "--target", "binary", "--zstd", "-o", zstd}).status == 0);
  REQUIRE(slurp(kept) == slurp(rmb));
  REQUIRE(decode_rmb_contents(slurp(again)).placed == built.placed);
  REQUIRE(decode_rmb_contents(slurp(zstd)).placed == built.placed);
  // The dump lists the section; decompiling says what the text leaves out.
  r = run_ramus({"dump", rmb});
  REQUIRE(r.status == 0);
  REQUIRE(r.out.find("-- section 12: placed pieces") != std::string::npos);
  r = run_ramus({"decompile", rmb, "-o", (dir.path / "a.ramus").string()});
  REQUIRE(r.status == 0);
  REQUIRE(r.out.find("ramus: note: the placed pieces (section 12: 2 tree(s)") != std::string::npos);
}
