// The project's only source of randomness.
//
// Same seed -> same numbers on every machine and standard library: the generator is SplitMix64
// (Steele, Lea & Flood, "Fast splittable pseudorandom number generators", OOPSLA 2014) and every
// distribution is implemented here, never with std::*_distribution, whose algorithms differ
// between libstdc++, libc++ and MSVC.
//
// Streams are derived by hashing a key, so a draw can depend only on (seed, step, position)
// and not on the order in which threads reach it: Rng::stream(seed, step, position).
#pragma once

#include <cstdint>

namespace ramus {

// SplitMix64's output function: a bijective 64-bit mixer.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

class Rng {
 public:
  constexpr explicit Rng(std::uint64_t seed = 0) : state_(seed) {}

  // A generator whose sequence depends only on the given keys.
  static constexpr Rng stream(std::uint64_t seed, std::uint64_t a, std::uint64_t b = 0) {
    return Rng(mix64(mix64(seed ^ 0x5851f42d4c957f2dULL) ^ mix64(a + 0x9e3779b97f4a7c15ULL) ^
                     mix64(b + 0x632be59bd9b4e019ULL) * 3));
  }

  constexpr std::uint64_t next_u64() {
    state_ += 0x9e3779b97f4a7c15ULL;
    return mix64(state_);
  }
  // Uniform in [0, 1) with 53 random bits.
  constexpr double uniform01() { return double(next_u64() >> 11) * 0x1.0p-53; }
  // Uniform in [a, b).
  constexpr double uniform(double a, double b) { return a + (b - a) * uniform01(); }
  // Uniform integer in [0, n) without modulo bias (Lemire's method); n > 0.
  std::uint64_t below(std::uint64_t n);
  // Normal with mean m and standard deviation s (Marsaglia's polar method).
  double normal(double m = 0.0, double s = 1.0);

  constexpr std::uint64_t state() const { return state_; }

 private:
  std::uint64_t state_;
};

}  // namespace ramus
