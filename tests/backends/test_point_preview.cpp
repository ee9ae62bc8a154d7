// The preview of a scan (backends/preview/point_preview.h): points drawn as dots in both views,
// upright, the same bytes for the same cloud, a stray point not shrinking the picture.
#include <catch2/catch.hpp>

#include "backends/preview/point_preview.h"
#include "core/rng.h"

using namespace ramus;
using namespace ramus::preview;

namespace {

// A 1 m wide, 4 m tall column of points (a trunk with a crown) about a UTM-like offset.
PointCloud column(std::size_t n) {
  PointCloud c;
  c.offset = {600000, 5000000, 100};
  Rng rng(11);
  for (std::size_t i = 0; i < n; ++i) {
    c.positions.push_back(
        Vec3f(Vec3{rng.uniform01() - 0.5, rng.uniform01() - 0.5, 4 * rng.uniform01()}));
  }
  return c;
}

struct Ink {
  int left_w = 0, left_h = 0, right_w = 0, right_h = 0;
};

// Width and height of the drawn (non-background) pixels in each half.
Ink ink(const std::vector<std::uint8_t>& rgb, int w, int h) {
  int lo[2][2] = {{w, h}, {w, h}}, hi[2][2] = {{-1, -1}, {-1, -1}};
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (x == w / 2) continue;  // the rule between the views
      const std::uint8_t* p = &rgb[(std::size_t(y) * w + x) * 3];
      if (p[0] > 200 && p[1] > 200 && p[2] > 200) continue;
      const int v = x < w / 2 ? 0 : 1;
      lo[v][0] = std::min(lo[v][0], x);
      lo[v][1] = std::min(lo[v][1], y);
      hi[v][0] = std::max(hi[v][0], x);
      hi[v][1] = std::max(hi[v][1], y);
    }
  }
  return {hi[0][0] - lo[0][0] + 1, hi[0][1] - lo[0][1] + 1, hi[1][0] - lo[1][0] + 1,
          hi[1][1] - lo[1][1] + 1};
}

}  // namespace

TEST_CASE("a scan is drawn upright in both views", "[preview][points]") {
  PreviewOptions o;
  o.width = 300;
  o.height = 200;
  const PointCloud c = column(20000);
  const auto rgb = render_points_rgb(c, o);
  REQUIRE(rgb.size() == 300 * 200 * 3);
  const Ink i = ink(rgb, 300, 200);
  CHECK(i.left_h > 150);  // fitted: the column fills the height less the margins
  CHECK(i.left_h > 2 * i.left_w);
  CHECK(i.right_h > 2 * i.right_w);
  CHECK(render_points_png(c, o) == render_points_png(c, o));
  CHECK(render_points_png(c, o).substr(1, 3) == "PNG");
  const std::string svg = render_points_svg(c, o);
  CHECK(svg.rfind("<svg", 0) == 0);
  CHECK(svg.find("<rect x=") != std::string::npos);
  CHECK(svg == render_points_svg(c, o));
}

TEST_CASE("a stray point does not shrink the scan's picture", "[preview][points]") {
  PreviewOptions o;
  o.width = 300;
  o.height = 200;
  PointCloud c = column(20000);
  const Ink before = ink(render_points_rgb(c, o), 300, 200);
  c.positions.push_back(Vec3f{40, 0, 30});  // a bird 40 m away
  const Ink after = ink(render_points_rgb(c, o), 300, 200);
  CHECK(after.left_h >= before.left_h - 2);
}

TEST_CASE("an empty scan and bad sizes are refused", "[preview][points]") {
  CHECK_THROWS_AS(render_points_rgb(PointCloud{}, {}), std::invalid_argument);
  PreviewOptions o;
  o.height = 4;
  CHECK_THROWS_AS(render_points_rgb(column(10), o), std::invalid_argument);
  CHECK_THROWS_AS(write_points_preview(column(10), "p.bmp", {}), std::invalid_argument);
}
