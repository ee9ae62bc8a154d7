#include "backends/texture/bark_exemplar.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/rng.h"

namespace ramus::texture {
namespace {

// Value noise: a hashed random value at every integer lattice point, smoothly interpolated.
// Periodic with period `px` across and `py` down, so the exemplar itself tiles (a seamless
// exemplar lets cuts near its border find matches too).
double lattice(std::uint64_t seed, std::int64_t x, std::int64_t y) {
  return double(mix64(seed ^ mix64(std::uint64_t(x) * 0x9e3779b97f4a7c15ULL + std::uint64_t(y))) >>
                11) *
         0x1.0p-53;
}

double value_noise(std::uint64_t seed, double x, double y, int px, int py) {
  const double fx = std::floor(x), fy = std::floor(y);
  const double tx = x - fx, ty = y - fy;
  const double sx = tx * tx * (3 - 2 * tx), sy = ty * ty * (3 - 2 * ty);
  auto at = [&](double ix, double iy) {
    auto wrap = [](std::int64_t v, int p) { return ((v % p) + p) % p; };
    return lattice(seed, wrap(std::int64_t(ix), px), wrap(std::int64_t(iy), py));
  };
  const double a = at(fx, fy), b = at(fx + 1, fy), c = at(fx, fy + 1), d = at(fx + 1, fy + 1);
  return (a + (b - a) * sx) + ((c + (d - c) * sx) - (a + (b - a) * sx)) * sy;
}

// Fractal sum of `octaves` octaves, base lattice fx x fy cells over the unit square; in [0, 1).
double fbm(std::uint64_t seed, double u, double v, int fx, int fy, int octaves) {
  double sum = 0, amp = 0.5, norm = 0;
  for (int o = 0; o < octaves; ++o) {
    sum += amp * value_noise(seed + std::uint64_t(o) * 7919, u * fx, v * fy, fx, fy);
    norm += amp;
    amp *= 0.5;
    fx *= 2;
    fy *= 2;
  }
  return sum / norm;
}

double smoothstep(double a, double b, double x) {
  double t = std::clamp((x - a) / (b - a), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

}  // namespace

Image bark_exemplar(int size, std::uint64_t seed, const BarkStyle& style) {
  if (size < 16) throw std::invalid_argument("bark_exemplar: size below 16");
  Image out(size, size);
  const std::uint64_t s = mix64(seed ^ 0x6261726bULL);  // "bark"
  const int furrows = std::max(1, int(std::lround(style.furrows)));
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const double u = (x + 0.5) / size, v = (y + 0.5) / size;
      // Furrows: the dark zero-crossings of a sine across, shifted sideways by low-frequency
      // noise that is stretched along the trunk, so they run mostly vertically and wander.
      const double warp = (fbm(s, u, v, 3, 2, 4) - 0.5) * 2 * style.warp;
      const double phase = (u * furrows + warp) * 2 * M_PI;
      const double ridge = std::abs(std::sin(phase));
      // Furrow width varies along the trunk and its flanks are ragged; plates split by short
      // horizontal cracks.
      const double rough = fbm(s + 5, u, v, 32, 24, 3) - 0.5;
      const double width = 0.3 + 0.45 * fbm(s + 1, u, v, 4, 6, 3) + 0.35 * rough;
      double depth = 1 - smoothstep(0.0, std::max(0.05, width), ridge);
      const double crack = fbm(s + 2, u, v, 24, 6, 2);
      depth = std::max(depth, 0.8 * smoothstep(0.72, 0.8, crack) * smoothstep(0.3, 0.6, ridge));
      // Plates are lit more in their middle (relief), with vertical grain, flakes and mottling.
      const double grain = fbm(s + 3, u, v, 64, 8, 3);
      const double flakes = fbm(s + 6, u, v, 40, 40, 2);
      const double mottle = fbm(s + 4, u, v, 8, 8, 4);
      const double shade = 0.55 + 0.3 * std::sqrt(ridge) + 0.4 * (grain - 0.5) +
                           0.3 * (flakes - 0.5) + 0.3 * (mottle - 0.5);
      for (int c = 0; c < 3; ++c) {
        double plate = style.plate[c] * shade;
        double value = plate + (style.furrow[c] - plate) * depth;
        out.at(x, y)[c] = std::uint8_t(std::clamp(std::lround(value * 255), 0L, 255L));
      }
    }
  }
  return out;
}

}  // namespace ramus::texture
