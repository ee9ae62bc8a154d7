// Connected pieces (infer/shape/pieces.h): node-parent links and touching endpoints join
// segments; separate roots and the turtle's pen-up moves do not.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "compiler/grow.h"
#include "infer/shape/pieces.h"
#include "infer/shape/tree_shape.h"
#include "shape_fixtures.h"

using namespace ramus;
using namespace shape_test;

TEST_CASE("pieces: a skeleton with two roots has two", "[shape]") {
  Skeleton s;
  chain(s, {0, 0, 0}, {0, 0, 3}, 3);
  chain(s, {2, 0, 0}, {2, 0, 1}, 1);
  const shape::Pieces p = shape::find_pieces(s);
  CHECK(p.count == 2);
  CHECK(p.total_length == Approx(4));
  CHECK(p.largest_length == Approx(3));
  CHECK(shape::measure_tree_shape(s).largest_piece_share == Approx(0.75));
  CHECK(p.piece_of_node[0] == 0);
  CHECK(p.piece_of_node[4] == 1);
}

TEST_CASE("pieces: a second root that starts where the first ends makes one piece", "[shape]") {
  Skeleton s;
  chain(s, {0, 0, 0}, {0, 0, 3}, 3);
  chain(s, {0, 0, 3 + 1e-7}, {1, 0, 4}, 2);  // 1e-7 apart: within 1e-6 of the height 4
  CHECK(shape::find_pieces(s).count == 1);
  Skeleton gap;
  chain(gap, {0, 0, 0}, {0, 0, 3}, 3);
  chain(gap, {0, 0, 3 + 1e-4}, {1, 0, 4}, 2);  // 1e-4 apart: two pieces
  CHECK(shape::find_pieces(gap).count == 2);
}

TEST_CASE("pieces: the turtle's pen-up move leaves two pieces", "[shape]") {
  // F f F: the turtle draws, moves without drawing, draws again.
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "ramus_shape_pieces_test";
  std::filesystem::create_directories(dir);
  const std::string file = (dir / "pen_up.ramus").string();
  std::ofstream(file) << "lsystem pen_up {\n  derive 0;\n  axiom F(1) f(1) F(1);\n}\n";
  SourceManager sources;
  DiagnosticSink diags;
  const Skeleton s = grow_file(file, {}, sources, diags);
  std::filesystem::remove_all(dir);
  REQUIRE_FALSE(diags.has_errors());
  const shape::TreeShape t = shape::measure_tree_shape(s);
  CHECK(t.pieces == 2);
  CHECK(t.largest_piece_share == Approx(0.5));
  CHECK(t.height == Approx(3));
}

TEST_CASE("pieces: zero-length segments and lonely roots are no pieces", "[shape]") {
  Skeleton s;
  chain(s, {0, 0, 0}, {0, 0, 1}, 1);
  SkeletonNode lonely;
  lonely.position = {5, 5, 5};
  s.add(lonely);
  chain(s, {7, 7, 7}, {7, 7, 7}, 1);  // a root and a child at the same place
  CHECK(shape::find_pieces(s).count == 1);
  CHECK(shape::find_pieces(Skeleton{}).count == 0);
}
