// The preview rasterizer and the PNG/SVG pictures.
#include <catch2/catch.hpp>
#include <filesystem>

#include "backends/mesh/leaf_shape.h"
#include "backends/preview/preview.h"
#include "backends/preview/raster.h"
#include "core/atomic_file.h"
#include "tests/mesh/synthetic_tree.h"

using namespace ramus;
using namespace ramus::preview;

namespace {

int covered(const Raster& r, float value) {
  int n = 0;
  for (int y = 0; y < r.height(); ++y) {
    for (int x = 0; x < r.width(); ++x) n += r.at(x, y).r == value;
  }
  return n;
}

}  // namespace

TEST_CASE("a quad covers exactly the pixels whose centres it contains", "[preview]") {
  Raster r(20, 20, {0, 0, 0});
  int calls = 0;
  auto fill = [&](float, float, float, Rgb& out) {
    ++calls;
    out = {1, 1, 1};
    return true;
  };
  // The quad [2,12) x [3,8) as two triangles sharing a diagonal, wound both ways.
  r.triangle({Vec3f{2, 3, 1}, Vec3f{12, 3, 1}, Vec3f{12, 8, 1}}, fill);
  r.triangle({Vec3f{2, 3, 0.5f}, Vec3f{2, 8, 0.5f}, Vec3f{12, 8, 0.5f}}, fill);
  CHECK(covered(r, 1) == 10 * 5);
  CHECK(calls == 10 * 5);  // the shared edge is not drawn twice
  CHECK(r.at(2, 3).r == 1);
  CHECK(r.at(11, 7).r == 1);
  CHECK(r.at(12, 7).r == 0);
  CHECK(r.at(1, 3).r == 0);
}

TEST_CASE("the depth buffer keeps the nearer triangle", "[preview]") {
  Raster r(8, 8, {0, 0, 0});
  auto colour = [](float c) {
    return [c](float, float, float, Rgb& out) {
      out = {c, c, c};
      return true;
    };
  };
  r.triangle({Vec3f{0, 0, 0.2f}, Vec3f{8, 0, 0.2f}, Vec3f{0, 8, 0.2f}}, colour(0.25f));
  r.triangle({Vec3f{0, 0, 0.5f}, Vec3f{8, 0, 0.5f}, Vec3f{0, 8, 0.5f}}, colour(0.75f));
  CHECK(r.at(1, 1).r == 0.25f);
  CHECK(r.depth(1, 1) == Approx(0.2f));
  // A discarding shader (alpha test) leaves the pixel alone.
  r.triangle({Vec3f{0, 0, 0}, Vec3f{8, 0, 0}, Vec3f{0, 8, 0}},
             [](float, float, float, Rgb&) { return false; });
  CHECK(r.at(1, 1).r == 0.25f);
}

TEST_CASE("supersampling averages the samples", "[preview]") {
  Raster r(4, 4, {0, 0, 0});
  r.triangle({Vec3f{0, 0, 0}, Vec3f{2, 0, 0}, Vec3f{2, 4, 0}}, [](float, float, float, Rgb& out) {
    out = {1, 1, 1};
    return true;
  });
  const auto px = r.resolve(2);
  REQUIRE(px.size() == 2 * 2 * 3);
  CHECK(px[0] > 0);
  CHECK(px[0] < 255);  // an edge pixel is grey
  CHECK(px[3] == 0);   // right half untouched
}

TEST_CASE("the preview shows the tree in both views", "[preview]") {
  mesh::MeshOptions mo;
  mo.leaf_scale = 5;
  const auto tree = mesh::build_tree_mesh(testing::synthetic_tree(3, 600), mo);
  PreviewOptions o;
  o.width = 200;
  o.height = 100;
  const auto rgb = render_rgb(tree, o);
  REQUIRE(rgb.size() == 200 * 100 * 3);
  int left = 0, right = 0, green = 0;
  for (int y = 0; y < 100; ++y) {
    for (int x = 0; x < 200; ++x) {
      const std::uint8_t* p = &rgb[(y * 200 + x) * 3];
      const bool ink = p[0] < 200 || p[1] < 200 || p[2] < 200;
      if (ink && x < 99) ++left;
      if (ink && x > 101) ++right;
      green += p[1] > p[0] + 20 && p[1] > p[2] + 20;
    }
  }
  CHECK(left > 200);
  CHECK(right > 200);
  CHECK(green > 50);  // leaves
  CHECK(render_png(tree, o) == render_png(tree, o));
  CHECK(render_png(tree, o).substr(1, 3) == "PNG");
}

TEST_CASE("the SVG preview has polygons and leaf outlines", "[preview]") {
  const auto tree = mesh::build_tree_mesh(testing::synthetic_tree(3, 200), {});
  const std::string svg = render_svg(tree, {});
  CHECK(svg.rfind("<svg", 0) == 0);
  CHECK(svg.find("<polygon") != std::string::npos);
  CHECK(svg.find("</svg>") != std::string::npos);
}

TEST_CASE("preview options and paths are checked", "[preview]") {
  const auto tree = mesh::build_tree_mesh(testing::synthetic_tree(3, 50), {});
  PreviewOptions o;
  o.width = 5;
  CHECK_THROWS_AS(render_rgb(tree, o), std::invalid_argument);
  CHECK_THROWS_AS(write_preview(tree, "/nonexistent-ramus-dir/p.png", {}), WriteError);
  CHECK_THROWS_AS(write_preview(tree, "p.bmp", {}), std::invalid_argument);
}

TEST_CASE("the leaf outline matches the leaf mask", "[preview]") {
  CHECK(mesh::leaf_inside(0.5, 0.5));
  CHECK_FALSE(mesh::leaf_inside(0.02, 0.5));
  CHECK_FALSE(mesh::leaf_inside(0.5, 1.01));
  for (const auto& p : mesh::leaf_outline(8)) {
    if (mesh::leaf_half_width(p[1]) < 1e-6) continue;  // the tip
    CHECK(mesh::leaf_inside(p[0] + (p[0] > 0.5 ? -1e-9 : 1e-9), p[1]));
    CHECK_FALSE(mesh::leaf_inside(p[0] + (p[0] > 0.5 ? 1e-6 : -1e-6), p[1]));
  }
}
