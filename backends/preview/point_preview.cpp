#include "backends/preview/point_preview.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>
#include <tuple>

#include "backends/preview/picture_file.h"
#include "backends/preview/png.h"
#include "backends/preview/view.h"

namespace ramus::preview {
namespace {

// Dot radius in output pixels: three quarters of a pixel for a dense terrestrial scan, so it
// reads as a surface with its gaps; larger for sparse ones (an airborne scan has a few thousand
// points per tree), up to 2 pixels, a third of the spacing the points would have if spread
// evenly over the view, so a sparse crown still reads as a crown and not as dust.
float dot_radius(const View& v, const Vec3& lo, const Vec3& hi, std::size_t points) {
  const double wide = std::max(hi.x - lo.x, hi.y - lo.y) * v.scale;
  const double tall = (hi.z - lo.z) * v.scale;
  const double spacing =
      std::sqrt(std::max(wide * tall, 1.0) / double(std::max<std::size_t>(points, 1)));
  return float(std::clamp(spacing / 3, 0.75, 2.0));
}
constexpr Rgb kScanColour{0.20f, 0.38f, 0.66f};

struct Bounds {
  Vec3 lo, hi;
};

// The box the views are fitted to: per axis the 0.1 % and 99.9 % quantiles of the points, so
// a few stray returns far from the tree (birds, dust, a wire) do not shrink it to a corner of
// the picture; they are still drawn where they fall inside it. Clouds of under 1000 points
// keep their extremes.
Bounds bounds_of(const PointCloud& cloud) {
  if (cloud.empty()) throw std::invalid_argument("the scan has no points to draw");
  const std::size_t n = cloud.size();
  const std::size_t low = std::size_t(0.001 * double(n - 1));
  const std::size_t high = n - 1 - low;
  Bounds b;
  std::vector<float> axis(n);
  for (int k = 0; k < 3; ++k) {
    for (std::size_t i = 0; i < n; ++i) axis[i] = cloud.positions[i][k];
    std::nth_element(axis.begin(), axis.begin() + std::ptrdiff_t(low), axis.end());
    b.lo[k] = axis[low];
    std::nth_element(axis.begin(), axis.begin() + std::ptrdiff_t(high), axis.end());
    b.hi[k] = axis[high];
  }
  return b;
}

// The depth range of the bounds in a view, so a dot's shade is its place between the nearest
// and the farthest point.
std::pair<double, double> depth_range(const View& v, const Bounds& b) {
  double lo = std::numeric_limits<double>::max(), hi = -lo;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 c{corner & 1 ? b.hi.x : b.lo.x, corner & 2 ? b.hi.y : b.lo.y,
                 corner & 4 ? b.hi.z : b.lo.z};
    const double d = dot(c - v.ref, v.forward);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  return {lo, hi};
}

Rgb depth_shade(double depth, std::pair<double, double> range) {
  const double span = range.second - range.first;
  const double t = span > 0 ? std::clamp((depth - range.first) / span, 0.0, 1.0) : 0.0;
  const float k = float(1.15 - 0.55 * t);
  return {std::min(1.0f, kScanColour.r * k), std::min(1.0f, kScanColour.g * k),
          std::min(1.0f, kScanColour.b * k)};
}

}  // namespace

std::vector<std::uint8_t> render_points_rgb(const PointCloud& cloud, const PreviewOptions& o) {
  check_preview_options(o);
  const Bounds b = bounds_of(cloud);
  const int f = o.supersample;
  Raster raster(o.width * f, o.height * f, kBackground);
  for (const View& view : make_views(b.lo, b.hi, o.width, o.height)) {
    const auto range = depth_range(view, b);
    const float radius = dot_radius(view, b.lo, b.hi, cloud.size()) * float(f);
    for (const Vec3f& p : cloud.positions) {
      const Vec3f q = view.project(p);
      raster.dot(q.x * float(f), q.y * float(f), q.z, radius, depth_shade(q.z, range));
    }
  }
  auto rgb = raster.resolve(f);
  draw_view_divider(rgb, o);
  return rgb;
}

std::string render_points_png(const PointCloud& cloud, const PreviewOptions& o) {
  const auto rgb = render_points_rgb(cloud, o);
  return encode_png(rgb.data(), o.width, o.height, 3);
}

std::string render_points_svg(const PointCloud& cloud, const PreviewOptions& o) {
  check_preview_options(o);
  const Bounds b = bounds_of(cloud);
  // (view, pixel row, pixel column) -> the nearest depth there; a std::map keeps the order
  // fixed, so the same scan gives the same bytes.
  std::map<std::tuple<int, int, int>, float> nearest;
  const auto views = make_views(b.lo, b.hi, o.width, o.height);
  for (int v = 0; v < 2; ++v) {
    for (const Vec3f& p : cloud.positions) {
      const Vec3f q = views[v].project(p);
      const int x = int(std::floor(q.x)), y = int(std::floor(q.y));
      if (x < 0 || y < 0 || x >= o.width || y >= o.height) continue;
      auto [it, fresh] = nearest.emplace(std::make_tuple(v, y, x), q.z);
      if (!fresh) it->second = std::min(it->second, q.z);
    }
  }
  struct Square {
    float depth;
    int x, y, view;
  };
  std::vector<Square> squares;
  squares.reserve(nearest.size());
  for (const auto& [key, depth] : nearest) {
    squares.push_back({depth, std::get<2>(key), std::get<1>(key), std::get<0>(key)});
  }
  // Back to front; ties in the map's order (stable sort), so the output is deterministic.
  std::stable_sort(squares.begin(), squares.end(),
                   [](const Square& a, const Square& c) { return a.depth > c.depth; });
  const std::pair<double, double> ranges[2] = {depth_range(views[0], b), depth_range(views[1], b)};
  std::string svg = svg_open(o.width, o.height);
  char buf[160];
  for (const Square& s : squares) {
    std::snprintf(buf, sizeof buf,
                  "<rect x=\"%d\" y=\"%d\" width=\"1\" height=\"1\" fill=\"%s\"/>\n", s.x, s.y,
                  svg_colour(depth_shade(s.depth, ranges[s.view])).c_str());
    svg += buf;
  }
  svg += "</svg>\n";
  return svg;
}

void write_points_preview(const PointCloud& cloud, const std::string& path,
                          const PreviewOptions& o) {
  write_picture(
      path, [&] { return render_points_png(cloud, o); },
      [&] { return render_points_svg(cloud, o); });
}

}  // namespace ramus::preview
