// Tree shape (infer/shape/tree_shape.h): axis-locked share and height on hand-made trees.
#include <catch2/catch.hpp>
#include <cmath>

#include "infer/shape/tree_shape.h"
#include "shape_fixtures.h"

using namespace ramus;
using namespace shape_test;

TEST_CASE("tree shape: the axis-locked share of a staircase", "[shape]") {
  Skeleton s;
  // Four axis steps of length 1 (x, z, y, z)...
  std::uint32_t at = chain(s, {0, 0, 0}, {1, 0, 0}, 1);
  at = chain(s, {1, 0, 0}, {1, 0, 1}, 1, at);
  at = chain(s, {1, 0, 1}, {1, 1, 1}, 1, at);
  at = chain(s, {1, 1, 1}, {1, 1, 2}, 1, at);
  // ...a diagonal of length sqrt(2), 45 degrees off every axis...
  at = chain(s, {1, 1, 2}, {2, 1, 3}, 1, at);
  // ...one segment 2 degrees off z (locked) and one 4 degrees off z (not), each of length 2.
  const Vec3 top{2, 1, 3};
  const Vec3 two = top + tilted(2, 0) * 2.0;
  at = chain(s, top, two, 1, at);
  chain(s, two, two + tilted(4, 90) * 2.0, 1, at);
  const shape::TreeShape t = shape::measure_tree_shape(s);
  CHECK(t.axis_locked_share == Approx((4 + 2) / (4 + std::sqrt(2.0) + 2 + 2)));
  CHECK(t.pieces == 1);
  CHECK(t.largest_piece_share == 1.0);
  CHECK(t.segments == 7);
  CHECK(t.total_length == Approx(8 + std::sqrt(2.0)));
  CHECK(t.height == Approx(3 + 2 * std::cos(2 * kPi / 180) + 2 * std::cos(4 * kPi / 180)));
}

TEST_CASE("tree shape: an empty skeleton measures zeros", "[shape]") {
  const shape::TreeShape t = shape::measure_tree_shape(Skeleton{});
  CHECK(t.pieces == 0);
  CHECK(t.largest_piece_share == 0.0);
  CHECK(t.axis_locked_share == 0.0);
  CHECK(t.height == 0.0);
  CHECK(std::isnan(t.lean_degrees));
}
