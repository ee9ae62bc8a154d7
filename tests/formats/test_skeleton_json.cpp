#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "core/rng.h"
#include "format_test_util.h"
#include "formats/skeleton_json.h"

using namespace ramus;
using namespace ramus::test;

namespace {

Skeleton sample_skeleton() {
  Skeleton s;
  Rng rng(42);
  SkeletonNode root;
  root.position = {0.1, -1.0 / 3.0, 1e-300};
  root.radius = 0.25;
  s.add(root);
  for (std::uint32_t i = 1; i < 20; ++i) {
    SkeletonNode n;
    n.position = {rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(0, 1e6)};
    n.heading = normalized(Vec3{rng.uniform(-1, 1), rng.uniform(-1, 1), 1.0});
    n.radius = rng.uniform(0, 0.2);
    n.parent = std::uint32_t(rng.uniform(0, double(i) - 1e-9));
    n.order = std::uint16_t(i % 4);
    if (i % 3 == 0) n.source_module = i * 11;
    s.add(n);
  }
  s.organ_kinds = {"leaf", "flower \"quoted\"\n"};
  OrganAnchor o;
  o.node = 7;
  o.position = {1.5, 2.5, 3.5};
  o.size = 0.125;
  o.kind = 1;
  s.organs.push_back(o);
  return s;
}

Skeleton parse(const std::string& text) { return skeleton_from_json(text, "s.json"); }

std::string with_nodes(const std::string& nodes) {
  return "{\"format\": \"ramus-skeleton\", \"version\": 1, \"nodes\": [" + nodes + "]}";
}

}  // namespace

TEST_CASE("skeleton_json: write then read gives back the same skeleton exactly", "[skeleton]") {
  const Skeleton s = sample_skeleton();
  auto dir = temp_dir("skeleton");
  const std::string path = (dir / "s.json").string();
  write_skeleton_json(path, s);
  Skeleton t = read_skeleton_json(path);
  REQUIRE(t.size() == s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    const SkeletonNode &a = s.nodes[i], &b = t.nodes[i];
    CHECK(a.position == b.position);
    CHECK(a.heading == b.heading);
    CHECK(a.left == b.left);
    CHECK(a.up == b.up);
    CHECK(a.radius == b.radius);
    CHECK(a.parent == b.parent);
    CHECK(a.order == b.order);
    CHECK(a.source_module == b.source_module);
  }
  CHECK(t.organ_kinds == s.organ_kinds);
  REQUIRE(t.organs.size() == 1);
  CHECK(t.organs[0].node == 7);
  CHECK(t.organs[0].position == Vec3{1.5, 2.5, 3.5});
  CHECK(t.organs[0].kind == 1);
  CHECK(skeleton_to_json(t) == skeleton_to_json(s));  // byte-identical on rewrite
  std::filesystem::remove_all(dir);
}

TEST_CASE("skeleton_json: an empty skeleton and defaults", "[skeleton]") {
  Skeleton empty = parse(skeleton_to_json(Skeleton{}));
  CHECK(empty.empty());
  Skeleton s =
      parse(with_nodes("{\"position\": [1, 2, 3]}, {\"position\": [1, 2, 4], \"parent\": 0}"));
  REQUIRE(s.size() == 2);
  CHECK(s.nodes[0].parent == kNoParent);
  CHECK(s.nodes[1].parent == 0);
  CHECK(s.nodes[1].heading == Vec3{0, 0, 1});
  CHECK(parse(with_nodes("{\"position\": [0, 0, 0], \"parent\": null}")).nodes[0].parent ==
        kNoParent);
}

TEST_CASE("skeleton_json: structural errors name the JSON location", "[skeleton][errors]") {
  CHECK(error_of([] {
          parse(
              with_nodes("{\"position\": [0, 0, 0]},\n {\"position\": [0, 0, 1], \"parent\": 5}"));
        }) ==
        "s.json: line 2, column 36: nodes[1].parent: parent 5 is out of range (the file has 2 "
        "nodes)");
  CHECK(error_of([] {
          parse(
              with_nodes("{\"position\": [0, 0, 0], \"parent\": 1}, "
                         "{\"position\": [0, 0, 1], \"parent\": 0}"));
        }).find("nodes: the parent links form a cycle through node") != std::string::npos);
  CHECK(error_of([] {
          parse(with_nodes("{\"position\": [0, 0, 0], \"parent\": 0}"));
        }).find("nodes: node 0 is its own parent") != std::string::npos);
  CHECK(error_of([] { parse(with_nodes("{\"position\": [0, 0], \"radius\": 1}")); }) ==
        "s.json: line 1, column 67: nodes[0].position: expected 3 numbers, found 2 values");
  CHECK(error_of([] {
          parse(with_nodes("{\"position\": [0, 0, 0], \"raduis\": 1}"));
        }).find("nodes[0].raduis: unknown key (expected one of position, heading") !=
        std::string::npos);
  CHECK(error_of([] {
          parse(with_nodes("{\"position\": [0, \"a\", 0]}"));
        }).find("nodes[0].position[1]: expected a number, found a string") != std::string::npos);
  CHECK(error_of([] {
          parse(with_nodes("{\"position\": [0, 0, 0], \"radius\": -1}"));
        }).find("nodes[0].radius: the radius must not be negative") != std::string::npos);
  CHECK(error_of([] {
          parse(with_nodes("{\"position\": [0, 0, 0], \"parent\": 0.5}"));
        }).find("nodes[0].parent: expected a whole number from -1") != std::string::npos);
  CHECK(error_of([] {
          parse("{\"format\": \"other\", \"version\": 1, \"nodes\": []}");
        }).find("format: expected \"format\": \"ramus-skeleton\"") != std::string::npos);
  CHECK(error_of([] {
          parse("{\"format\": \"ramus-skeleton\", \"version\": 2, \"nodes\": []}");
        }).find("version: unsupported version") != std::string::npos);
  CHECK(error_of([] {
          parse("{\"format\": \"ramus-skeleton\", \"version\": 1}");
        }).find("nodes: missing \"nodes\"") != std::string::npos);
}

TEST_CASE("skeleton_json: syntax errors give line and column", "[skeleton][errors]") {
  CHECK(error_of([] { parse("{\n  \"format\": \"ramus-skeleton\",\n  \"version\": 1,\n}"); }) ==
        "s.json: line 4, column 1: expected a key in double quotes, found '}'");
  CHECK(error_of([] { parse("[1, 2,, 3]"); }) ==
        "s.json: line 1, column 7: expected a value, found ', 3]'");
  CHECK(error_of([] { parse("{\"a\": 1, \"a\": 2}"); }) ==
        "s.json: line 1, column 10: duplicate key 'a'");
  CHECK(error_of([] { parse("[01]"); }) ==
        "s.json: line 1, column 3: expected ',' or ']', found '1'");
  CHECK(error_of([] { parse("\"abc"); }) ==
        "s.json: line 1, column 5: the file ends inside a string");
  CHECK(error_of([] { parse("1e999"); }).find("is out of range") != std::string::npos);
  CHECK(error_of([] { parse(""); }) ==
        "s.json: line 1, column 1: expected a value, found the end of the file");
  CHECK(error_of([] { parse("{} x"); }) ==
        "s.json: line 1, column 4: unexpected 'x' after the value");
  CHECK(error_of([] { parse(std::string(100000, '[')); }).find("nested more than 200 deep") !=
        std::string::npos);
  CHECK(error_of([] { parse("\"\\ud800\""); }).find("low surrogate") != std::string::npos);
}

TEST_CASE("skeleton_json: non-finite numbers are refused by the writer", "[skeleton][errors]") {
  Skeleton s;
  SkeletonNode n;
  n.position = {std::nan(""), 0, 0};
  s.add(n);
  CHECK_THROWS_AS(skeleton_to_json(s), WriteError);
}

TEST_CASE("skeleton_json: every truncation is an error never a crash", "[skeleton][fuzz]") {
  const std::string text = skeleton_to_json(sample_skeleton());
  for (std::size_t len = 0; len + 1 < text.size(); ++len) {
    // Dropping the final newline still leaves a complete document; anything shorter does not.
    CHECK_THROWS_AS(parse(text.substr(0, len)), FormatError);
  }
  CHECK(parse(text.substr(0, text.size() - 1)).size() == 20);
}
