#include "core/rng.h"

#include <cmath>

namespace ramus {

__extension__ typedef unsigned __int128 u128;

std::uint64_t Rng::below(std::uint64_t n) {
  // Lemire, "Fast random integer generation in an interval", ACM TOMACS 2019.
  u128 m = (u128)next_u64() * n;
  std::uint64_t low = std::uint64_t(m);
  if (low < n) {
    std::uint64_t threshold = (0 - n) % n;
    while (low < threshold) {
      m = (u128)next_u64() * n;
      low = std::uint64_t(m);
    }
  }
  return std::uint64_t(m >> 64);
}

double Rng::normal(double m, double s) {
  // Polar method: uses only sqrt (exact in IEEE 754) and log, and consumes a deterministic
  // number of draws for a given state. The second value of the pair is discarded so that a
  // draw is a pure function of the state (no hidden cache that would break stream keying).
  for (;;) {
    double u = 2.0 * uniform01() - 1.0;
    double v = 2.0 * uniform01() - 1.0;
    double q = u * u + v * v;
    if (q > 0.0 && q < 1.0) {
      return m + s * u * std::sqrt(-2.0 * std::log(q) / q);
    }
  }
}

}  // namespace ramus
