#include "cli/compare_picture.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "backends/preview/png.h"
#include "backends/preview/raster.h"
#include "core/atomic_file.h"
#include "infer/shape/edge_samples.h"
#include "infer/shape/tree_base.h"

namespace ramus::cli {

namespace {

using preview::Raster;
using preview::Rgb;

constexpr int kPanelWidth = 320;   // output pixels per column
constexpr int kPanelHeight = 400;  // per row
constexpr int kSupersample = 3;
constexpr double kMargin = 0.06;
constexpr double kExtentPercentile = 0.995;
constexpr Rgb kBackground{0.96f, 0.96f, 0.94f};
constexpr Rgb kPointColour{0.25f, 0.42f, 0.62f};
constexpr Rgb kReconstructionColour{0.62f, 0.22f, 0.14f};
constexpr Rgb kTreeColour{0.40f, 0.29f, 0.18f};
constexpr Rgb kOtherTreeColour{0.20f, 0.45f, 0.25f};
constexpr Rgb kRuleColour{0.70f, 0.70f, 0.68f};

// One column: scan points, or a skeleton, placed at its own base.
struct Panel {
  const PointCloud* cloud = nullptr;
  const Skeleton* tree = nullptr;
  Rgb colour;
  shape::TreeBase base;
};

// The orthographic views of the picture: front looks along +y (x right), side along +x (-y
// right, so that the view is right-handed like the front one); z is up in both.
struct Projection {
  Vec3 right, forward;
  double scale = 1;       // raster pixels per unit
  double cx = 0, cy = 0;  // raster position of the base
};

Vec3f project(const Projection& v, const Vec3& base, const Vec3& p) {
  const Vec3 d = p - base;
  return Vec3f(Vec3{v.cx + v.scale * dot(d, v.right), v.cy - v.scale * d.z, dot(d, v.forward)});
}

// A screen-aligned quad from a to b, `width` raster pixels wide (points: a == b, a square).
void quad(Raster& r, Vec3f a, Vec3f b, float width, Rgb colour) {
  float dx = b.x - a.x, dy = b.y - a.y;
  const float len = std::sqrt(dx * dx + dy * dy);
  const float h = width / 2;
  if (len < 1e-6f) {
    dx = 1;
    dy = 0;
    a.x -= h;
    b.x += h;
  } else {
    dx /= len;
    dy /= len;
  }
  const Vec3f n{-dy * h, dx * h, 0};
  const auto fill = [colour](float, float, float, Rgb& out) {
    out = colour;
    return true;
  };
  r.triangle({a + n, b + n, b - n}, fill);
  r.triangle({a + n, b - n, a - n}, fill);
}

std::vector<Vec3> panel_points(const Panel& p) {
  if (p.cloud != nullptr) {
    std::vector<Vec3> out = shape::cloud_points(*p.cloud);
    for (Vec3& q : out) q += p.cloud->offset;  // same frame as its reconstruction
    return out;
  }
  // Samples as the envelope takes them, so the drawn base is the measured one.
  double lo = 0, hi = 0;
  if (!shape::segment_z_range(*p.tree, lo, hi)) return {};
  const double step = hi > lo ? (hi - lo) / 128 : 1.0;
  return shape::sample_edges(*p.tree, step);
}

double percentile(std::vector<double>& v, double share) {
  const std::size_t k = std::size_t(share * double(v.size() - 1));
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
  return v[k];
}

void draw_panel(Raster& r, const Panel& p, const Projection& v) {
  if (p.cloud != nullptr) {
    for (const Vec3f& q : p.cloud->positions) {
      const Vec3f s = project(v, p.base.axis, p.cloud->offset + Vec3(q));
      quad(r, s, s, float(kSupersample) * 1.2f, p.colour);
    }
    return;
  }
  for (const SkeletonNode& n : p.tree->nodes) {
    if (n.parent == kNoParent) continue;
    const SkeletonNode& m = p.tree->nodes[n.parent];
    // True width where it shows, never thinner than one output pixel.
    const float w = std::max(float(kSupersample), float(v.scale * (n.radius + m.radius)));
    quad(r, project(v, p.base.axis, m.position), project(v, p.base.axis, n.position), w, p.colour);
  }
}

}  // namespace

void write_compare_picture(const std::string& path, const std::vector<const CompareSide*>& sides) {
  std::vector<Panel> panels;
  std::size_t grown = 0;  // sides of grown or given trees so far, for their colour
  for (const CompareSide* side : sides) {
    const Rgb colour =
        side->cloud ? kReconstructionColour : (grown++ % 2 == 0 ? kTreeColour : kOtherTreeColour);
    if (side->cloud) panels.push_back({&*side->cloud, nullptr, kPointColour, {}});
    const std::size_t n = side->kind == SourceKind::Grammar
                              ? std::min(side->trees.size(), kPictureSeeds)
                              : side->trees.size();
    for (std::size_t i = 0; i < n; ++i) {
      panels.push_back({nullptr, &side->trees[i], colour, {}});
    }
  }
  // One scale for all: the widest half-width and the tallest height above a base, each the
  // 99.5th percentile of its panel, so that a stray point of a scan (pytlidar_tree_1 has one
  // 9 m beside the crown) does not shrink every tree; what lies beyond is cut at the edge.
  double half = 1e-12, tall = 1e-12;
  for (Panel& p : panels) {
    const std::vector<Vec3> pts = panel_points(p);
    if (pts.empty()) continue;
    p.base = shape::find_base(pts);
    std::vector<double> across, up;
    for (const Vec3& q : pts) {
      across.push_back(std::max(std::abs(q.x - p.base.axis.x), std::abs(q.y - p.base.axis.y)));
      up.push_back(q.z - p.base.axis.z);
    }
    half = std::max(half, percentile(across, kExtentPercentile));
    tall = std::max(tall, percentile(up, kExtentPercentile));
  }
  const int pw = kPanelWidth * kSupersample, ph = kPanelHeight * kSupersample;
  const double scale = std::min(pw * (1 - 2 * kMargin) / (2 * half), ph * (1 - 2 * kMargin) / tall);
  const int cols = int(panels.size());
  const int out_w = kPanelWidth * cols, out_h = kPanelHeight * 2;
  std::vector<std::uint8_t> image(std::size_t(out_w) * out_h * 3);
  for (int row = 0; row < 2; ++row) {
    Projection v;
    v.right = row == 0 ? Vec3{1, 0, 0} : Vec3{0, -1, 0};
    v.forward = row == 0 ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
    v.scale = scale;
    v.cx = pw / 2.0;
    v.cy = ph * (1 - kMargin);
    for (int c = 0; c < cols; ++c) {
      Raster r(pw, ph, kBackground);
      // A ground line and a rule between columns, so the panels read as separate.
      quad(r, Vec3f{0, float(v.cy), 1e9f}, Vec3f{float(pw), float(v.cy), 1e9f}, 2, kRuleColour);
      if (c > 0) quad(r, Vec3f{1, 0, 1e9f}, Vec3f{1, float(ph), 1e9f}, 2, kRuleColour);
      draw_panel(r, panels[std::size_t(c)], v);
      const std::vector<std::uint8_t> px = r.resolve(kSupersample);
      for (int y = 0; y < kPanelHeight; ++y) {
        std::copy_n(
            &px[std::size_t(y) * kPanelWidth * 3], kPanelWidth * 3,
            &image[((std::size_t(row) * kPanelHeight + y) * out_w + std::size_t(c) * kPanelWidth) *
                   3]);
      }
    }
  }
  // A WriteError reaches main, which reports it with exit code 1.
  write_file_atomically(path, preview::encode_png(image.data(), out_w, out_h, 3));
}

}  // namespace ramus::cli
