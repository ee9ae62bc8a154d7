#include "backends/mesh/leaf_shape.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "backends/preview/png.h"
#include "core/rng.h"

namespace ramus::mesh {

double leaf_half_width(double v) {
  constexpr double kPetiole = 0.12;  // fraction of the card taken by the stalk
  if (v < 0 || v > 1) return 0;
  if (v < kPetiole) return 0.035;
  const double b = (v - kPetiole) / (1 - kPetiole);  // 0..1 along the blade
  // Ovate: widest at about a third of the blade, rounded base, pointed tip.
  return 0.47 * std::pow(std::sin(std::numbers::pi * std::pow(b, 0.75)), 0.8);
}

std::vector<std::array<double, 2>> leaf_outline(int samples) {
  std::vector<std::array<double, 2>> pts;
  samples = std::max(samples, 3);
  for (int i = 0; i <= samples; ++i) {  // up the right side
    const double v = double(i) / samples;
    pts.push_back({0.5 + std::max(leaf_half_width(v), 0.0), v});
  }
  for (int i = samples - 1; i >= 0; --i) {  // down the left side
    const double v = double(i) / samples;
    pts.push_back({0.5 - std::max(leaf_half_width(v), 0.0), v});
  }
  return pts;
}

// Row y of the image holds v = (y + 0.5) / height: glTF puts texture coordinate (0, 0) at the
// image's top-left, so the petiole is at the top of the picture.
std::string leaf_texture_png(int w, int h) {
  std::vector<std::uint8_t> px(std::size_t(w) * h * 4);
  for (int y = 0; y < h; ++y) {
    const double v = (y + 0.5) / h;
    for (int x = 0; x < w; ++x) {
      const double u = (x + 0.5) / w;
      const double hw = leaf_half_width(v);
      const double off = std::abs(u - 0.5);
      const bool in = off <= hw;
      // Lighter midrib and veins, darker toward the margin.
      const double vein = std::abs(std::fmod(v * 9 + off * 12, 1.0) - 0.5) < 0.06 ? 0.12 : 0.0;
      const double rib = off < 0.02 ? 0.2 : 0.0;
      const double shade = 0.85 + 0.15 * (hw > 0 ? 1 - off / hw : 0) + vein + rib;
      std::uint8_t* p = &px[(std::size_t(y) * w + x) * 4];
      p[0] = std::uint8_t(std::clamp(70 * shade, 0.0, 255.0));
      p[1] = std::uint8_t(std::clamp(135 * shade, 0.0, 255.0));
      p[2] = std::uint8_t(std::clamp(45 * shade, 0.0, 255.0));
      p[3] = in ? 255 : 0;
    }
  }
  return preview::encode_png(px.data(), w, h, 4);
}

// Tileable bark: vertical furrows (periodic in u) with seeded per-column variation.
std::string bark_texture_png(int w, int h) {
  std::vector<std::uint8_t> px(std::size_t(w) * h * 3);
  Rng rng(0x6261726b);
  std::vector<double> column(w);
  for (double& c : column) c = rng.uniform(-0.08, 0.08);
  for (int y = 0; y < h; ++y) {
    const double v = double(y) / h;
    for (int x = 0; x < w; ++x) {
      const double u = double(x) / w;
      const double furrow =
          0.5 +
          0.5 * std::sin(2 * std::numbers::pi * (6 * u + 0.3 * std::sin(2 * std::numbers::pi * v)));
      const double shade = 0.7 + 0.3 * std::pow(furrow, 3) + column[x];
      std::uint8_t* p = &px[(std::size_t(y) * w + x) * 3];
      p[0] = std::uint8_t(std::clamp(120 * shade, 0.0, 255.0));
      p[1] = std::uint8_t(std::clamp(92 * shade, 0.0, 255.0));
      p[2] = std::uint8_t(std::clamp(66 * shade, 0.0, 255.0));
    }
  }
  return preview::encode_png(px.data(), w, h, 3);
}

}  // namespace ramus::mesh
