#include <catch2/catch.hpp>

#include "core/skeleton.h"

using namespace ramus;

namespace {
Skeleton make_y() {
  Skeleton s;
  s.add({.position = {0, 0, 0}, .radius = 0.2});
  s.add({.position = {0, 0, 1}, .radius = 0.15, .parent = 0});
  s.add({.position = {-0.5, 0, 2}, .radius = 0.1, .parent = 1, .order = 1});
  s.add({.position = {0.5, 0, 2}, .radius = 0.1, .parent = 1});
  return s;
}
}  // namespace

TEST_CASE("skeleton: children, roots, length and bounds", "[skeleton]") {
  Skeleton s = make_y();
  auto c = s.children();
  CHECK(c.count(0) == 1);
  CHECK(c.count(1) == 2);
  CHECK(*c.begin(1) == 2);
  CHECK(c.count(2) == 0);
  CHECK(s.roots() == std::vector<std::uint32_t>{0});
  CHECK(s.total_length() == Approx(1 + 2 * std::sqrt(1.25)));
  Vec3 lo, hi;
  s.bounds(lo, hi);
  CHECK(lo == Vec3{-0.5, 0, 0});
  CHECK(hi == Vec3{0.5, 0, 2});
  CHECK(s.validate().empty());
}

TEST_CASE("skeleton: validate rejects malformed skeletons", "[skeleton]") {
  Skeleton s = make_y();
  s.nodes[0].parent = 3;  // 0 -> 3 -> 1 -> 0
  CHECK(s.validate().find("cycle") != std::string::npos);
  s = make_y();
  s.nodes[2].parent = 17;
  CHECK(s.validate().find("out of range") != std::string::npos);
  s = make_y();
  s.nodes[1].radius = -1;
  CHECK(s.validate().find("radius") != std::string::npos);
  s = make_y();
  s.nodes[3].position.x = std::nan("");
  CHECK(s.validate().find("non-finite") != std::string::npos);
}
