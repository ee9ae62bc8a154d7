#include "backends/texture/bark_exemplar.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/rng.h"

namespace ramus::texture {
namespace {

// A hashed random value at every integer lattice point.
double lattice(std::uint64_t seed, std::int64_t x, std::int64_t y) {
  return double(mix64(seed ^ mix64(std::uint64_t(x) * 0x9e3779b97f4a7c15ULL + std::uint64_t(y))) >>
                11) *
         0x1.0p-53;
}

// The lattice values of one octave, px x py of them (the noise's period), computed once: an
// exemplar of 1024 x 1024 pixels samples 21 octaves per pixel, and hashing four corners per sample
// cost two thirds of a mesh build. The values and the interpolation are those of the hashed
// lattice, so the picture is the same to the bit.
struct LatticeTable {
  int px = 0, py = 0;
  std::vector<double> values;  // row-major, py rows of px

  LatticeTable(std::uint64_t seed, int px_, int py_)
      : px(px_), py(py_), values(std::size_t(px_) * py_) {
    for (int y = 0; y < py; ++y)
      for (int x = 0; x < px; ++x) values[std::size_t(y) * px + x] = lattice(seed, x, y);
  }

  double at(double ix, double iy) const {
    // Samples of the unit square reach one cell past the period at most; the modulo is for
    // the rest.
    auto wrap = [](std::int64_t v, int p) {
      if (v >= 0 && v < p) return int(v);
      if (v == p) return 0;
      return int(((v % p) + p) % p);
    };
    return values[std::size_t(wrap(std::int64_t(iy), py)) * px + wrap(std::int64_t(ix), px)];
  }

  // Value noise: the lattice smoothly interpolated. Periodic with period px across and py down,
  // so the exemplar itself tiles (a seamless exemplar lets cuts near its border find matches too).
  double noise(double x, double y) const {
    const double fx = std::floor(x), fy = std::floor(y);
    const double tx = x - fx, ty = y - fy;
    const double sx = tx * tx * (3 - 2 * tx), sy = ty * ty * (3 - 2 * ty);
    const double a = at(fx, fy), b = at(fx + 1, fy), c = at(fx, fy + 1), d = at(fx + 1, fy + 1);
    return (a + (b - a) * sx) + ((c + (d - c) * sx) - (a + (b - a) * sx)) * sy;
  }
};

// Fractal sum of `octaves` octaves, base lattice fx x fy cells over the unit square; in [0, 1).
class Fbm {
 public:
  Fbm(std::uint64_t seed, int fx, int fy, int octaves) : fx_(fx), fy_(fy) {
    for (int o = 0; o < octaves; ++o) {
      tables_.emplace_back(seed + std::uint64_t(o) * 7919, fx, fy);
      fx *= 2;
      fy *= 2;
    }
  }

  double operator()(double u, double v) const {
    double sum = 0, amp = 0.5, norm = 0;
    int fx = fx_, fy = fy_;
    for (const LatticeTable& t : tables_) {
      sum += amp * t.noise(u * fx, v * fy);
      norm += amp;
      amp *= 0.5;
      fx *= 2;
      fy *= 2;
    }
    return sum / norm;
  }

 private:
  int fx_, fy_;
  std::vector<LatticeTable> tables_;
};

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
  const Fbm warp_noise(s, 3, 2, 4), rough_noise(s + 5, 32, 24, 3), width_noise(s + 1, 4, 6, 3),
      crack_noise(s + 2, 24, 6, 2), grain_noise(s + 3, 64, 8, 3), flake_noise(s + 6, 40, 40, 2),
      mottle_noise(s + 4, 8, 8, 4);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const double u = (x + 0.5) / size, v = (y + 0.5) / size;
      // Furrows: the dark zero-crossings of a sine across, shifted sideways by low-frequency
      // noise that is stretched along the trunk, so they run mostly vertically and wander.
      const double warp = (warp_noise(u, v) - 0.5) * 2 * style.warp;
      const double phase = (u * furrows + warp) * 2 * M_PI;
      const double ridge = std::abs(std::sin(phase));
      // Furrow width varies along the trunk and its flanks are ragged; plates split by short
      // horizontal cracks.
      const double rough = rough_noise(u, v) - 0.5;
      const double width = 0.3 + 0.45 * width_noise(u, v) + 0.35 * rough;
      double depth = 1 - smoothstep(0.0, std::max(0.05, width), ridge);
      const double crack = crack_noise(u, v);
      depth = std::max(depth, 0.8 * smoothstep(0.72, 0.8, crack) * smoothstep(0.3, 0.6, ridge));
      // Plates are lit more in their middle (relief), with vertical grain, flakes and mottling.
      const double grain = grain_noise(u, v);
      const double flakes = flake_noise(u, v);
      const double mottle = mottle_noise(u, v);
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
