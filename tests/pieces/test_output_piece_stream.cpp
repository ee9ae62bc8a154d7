// The placed-pieces stream of the pieces back end (backends/pieces/output_piece_stream.h): on
// bench_pieces' own trees it takes at most 12 bytes per piece and its expansion (formats/rmb/
// rmb_piece_stream_expand.h, what the runtime runs) is the instance buffer byte for byte; the
// same for posed copies and trees fitted to grown skeletons once the forest carries the
// stream's dequantized poses, which move no bone by more than the quantization allows.
#include <catch2/catch.hpp>
#include <cmath>

#include "backends/pieces/output_instance_buffer.h"
#include "backends/pieces/output_layout.h"
#include "backends/pieces/output_piece_stream.h"
#include "bench/bench_pieces_trees.h"
#include "compiler/grow.h"
#include "formats/rmb/rmb_codec.h"
#include "formats/rmb/rmb_piece_stream_expand.h"
#include "output_fixture.h"

using namespace ramus;
using namespace ramus::pieces;

namespace {

std::size_t section_size(const RmbPieceStream& s) {
  rmb::Writer w;
  write_rmb_piece_stream(w, s);
  return w.size();
}

std::string buffer_of(const PieceSet& set, const Forest& f) {
  return encode_instance_buffer(set, f, "t.bin").binary;
}

std::vector<std::uint64_t> copy_seeds(std::uint64_t seed, std::size_t trees) {
  std::vector<std::uint64_t> s;
  for (std::size_t k = 0; k < trees; ++k) s.push_back(seed + k);
  return s;
}

// The largest distance a bone's world origin moved, relative to the tree's extent.
double largest_move(const PieceSet& set, const Forest& before, const Forest& after) {
  const PiecesLayout a = layout_forest(set, before), b = layout_forest(set, after);
  double move = 0, extent = 1e-9;
  for (std::size_t i = 0; i < a.bone_world.size(); ++i) {
    move = std::max(move, length(a.bone_world[i].t - b.bone_world[i].t));
    extent = std::max(extent, length(a.bone_world[i].t - a.bone_world[0].t));
  }
  return move / extent;
}

}  // namespace

TEST_CASE("bench_pieces' trees: at most 12 bytes per piece, expanded to the instance buffer",
          "[pieces][stream]") {
  const PieceSet set = bench::lower_bench_piece_set();
  Rng rng(1);
  std::size_t pieces = 0, section = 0, records = 0;
  for (std::size_t k = 0; k < 12; ++k) {
    const AssembleOptions ao = bench::bench_tree_options(rng, 1, k);
    Forest f;
    f.trees.push_back(assemble(set, ao));
    const std::uint64_t seed[] = {ao.seed};
    const Forest before = f;
    const RmbPieceStream s = quantize_forest_poses(set, f, seed);
    // Rest poses are stored exactly: quantizing changes no bit of the forest.
    REQUIRE(buffer_of(set, f) == buffer_of(set, before));
    REQUIRE(expand_piece_stream_binary(s) == buffer_of(set, f));
    INFO("tree " << k << ": " << f.trees[0].pieces.size() << " pieces, section " << section_size(s)
                 << " bytes");
    CHECK(section_size(s) <= 12 * f.trees[0].pieces.size());
    pieces += f.trees[0].pieces.size();
    section += section_size(s);
    records += rmb_piece_stream_tree_bytes(s);
    // Through a whole .rmb and back.
    const std::string file = encode_rmb(ir::make_grammar(""), {}, {}, s);
    REQUIRE(decode_rmb_contents(file).placed == s);
  }
  INFO(double(section) / pieces << " bytes per piece (section), " << double(records) / pieces
                                << " (tree records)");
  REQUIRE(double(section) / double(pieces) <= 12.0);
  REQUIRE(double(records) / double(pieces) <= 6.0);
}

TEST_CASE("posed copies and fitted trees expand to their instance buffer once quantized",
          "[pieces][stream]") {
  SECTION("posed copies: turned joints") {
    const PieceSet set = output_test::lower_set();
    Forest f = output_test::forest(set, 5, 4);
    const Forest before = f;
    const RmbPieceStream s = quantize_forest_poses(set, f, copy_seeds(5, 4));
    REQUIRE(expand_piece_stream_binary(s) == buffer_of(set, f));
    const double move = largest_move(set, before, f);
    CHECK(move > 0);     // the poses were quantized ...
    CHECK(move < 1e-4);  // ... within the rotation quantum, along whole branches
    // The stream's poses are fixed points: quantizing again changes nothing.
    const Forest once = f;
    REQUIRE(quantize_forest_poses(set, f, copy_seeds(5, 4)) == s);
    REQUIRE(buffer_of(set, f) == buffer_of(set, once));
  }
  SECTION("a tree fitted to a grown skeleton: moved joints") {
    const std::string file = std::string(RAMUS_SOURCE_DIR) + "/examples/pieces/grown.ramus";
    SourceManager sm;
    DiagnosticSink diags;
    const Program prog = load_program(file, sm, diags);
    const PieceSet set = lower_pieces(prog, sm, {}, diags);
    REQUIRE(!diags.has_errors());
    const Skeleton sk = grow_file(file, {}, sm, diags);
    FitOptions fo;
    fo.seed = 9;
    Forest f;
    f.trees.push_back(fit_skeleton(set, sk, fo));
    const Forest before = f;
    const std::uint64_t seed[] = {9};
    const RmbPieceStream s = quantize_forest_poses(set, f, seed);
    REQUIRE(expand_piece_stream_binary(s) == buffer_of(set, f));
    CHECK(largest_move(set, before, f) < 1e-4);
  }
}

TEST_CASE("the stream refuses a forest it cannot reproduce", "[pieces][stream]") {
  const PieceSet set = output_test::lower_set();
  Forest f = output_test::forest(set, 5, 1);
  const std::uint64_t wrong[] = {6};
  REQUIRE_THROWS_WITH(encode_piece_stream(set, f, wrong),
                      Catch::Contains("its tiles are not the draw of tile seed 6"));
  REQUIRE_THROWS_WITH(encode_piece_stream(set, f, {}), Catch::Contains("one tile seed per tree"));
  Forest moved = f;
  moved.trees[0].bones[1].parent = kNone;
  const std::uint64_t right[] = {5};
  REQUIRE_THROWS_WITH(encode_piece_stream(set, moved, right), Catch::Contains("is not its joint"));
}
