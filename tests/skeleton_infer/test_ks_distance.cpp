// The two-sample Kolmogorov-Smirnov statistic: hand-computed cases, properties, and agreement
// with scipy.stats.ks_2samp (python3-scipy, installed by scripts/install-deps.sh).
#include <catch2/catch.hpp>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/number_text.h"
#include "core/rng.h"
#include "infer/skeleton/fidelity.h"
#include "skeleton_fixtures.h"

using namespace ramus;
using skeleton_infer::ks_distance;

TEST_CASE("ks: hand-computed statistics", "[skeleton_infer]") {
  CHECK(ks_distance({1, 2, 3}, {1, 2, 3}) == 0);
  CHECK(ks_distance({1, 2, 3}, {4, 5, 6}) == 1);
  CHECK(ks_distance({}, {}) == 0);
  CHECK(ks_distance({1}, {}) == 1);
  // F_a steps 1/2 at 1 and 2; F_b 1/3 at 1.5, 2.5, 3.5: max gap 2/3 after 2 (1 - 1/3).
  CHECK(ks_distance({1, 2}, {1.5, 2.5, 3.5}) == Approx(2.0 / 3));
  // Ties across the samples step together: {1,1,2} vs {1,2,2} differ by 1/3 at x = 1.
  CHECK(ks_distance({1, 1, 2}, {1, 2, 2}) == Approx(1.0 / 3));
}

TEST_CASE("ks: symmetric, in [0, 1], invariant under monotone maps", "[skeleton_infer]") {
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    Rng rng(seed);
    std::vector<double> a, b, ea, eb;
    const auto na = 1 + rng.below(60), nb = 1 + rng.below(60);
    for (std::uint64_t i = 0; i < na; ++i) a.push_back(std::round(rng.normal(0, 2)));
    for (std::uint64_t i = 0; i < nb; ++i) b.push_back(std::round(rng.normal(0.5, 2)));
    for (double x : a) ea.push_back(std::exp(x));
    for (double x : b) eb.push_back(std::exp(x));
    const double d = ks_distance(a, b);
    CHECK(d >= 0);
    CHECK(d <= 1);
    CHECK(d == ks_distance(b, a));
    CHECK(d == Approx(ks_distance(ea, eb)));
  }
}

TEST_CASE("ks: agrees with scipy.stats.ks_2samp", "[skeleton_infer]") {
  // Samples with ties (rounded) and without, of different sizes.
  std::ostringstream script;
  std::vector<double> ours;
  script << "from scipy.stats import ks_2samp\n";
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    Rng rng(seed);
    std::vector<double> a, b;
    const auto na = 2 + rng.below(200), nb = 2 + rng.below(200);
    const bool ties = seed % 2 == 0;
    for (std::uint64_t i = 0; i < na; ++i) {
      const double x = rng.normal(0, 1);
      a.push_back(ties ? std::round(x * 4) / 4 : x);
    }
    for (std::uint64_t i = 0; i < nb; ++i) {
      const double x = rng.normal(seed % 3 == 0 ? 0.3 : 0.0, 1.2);
      b.push_back(ties ? std::round(x * 4) / 4 : x);
    }
    ours.push_back(ks_distance(a, b));
    script << "print(repr(ks_2samp([";
    for (double x : a) script << shortest_text(x) << ",";
    script << "], [";
    for (double x : b) script << shortest_text(x) << ",";
    script << "]).statistic))\n";
  }
  const std::string path = skeleton_test::write_temp("ks_check.py", script.str());
  // The system interpreter has python3-scipy; a python3 first on PATH may not.
  const std::string cmd = "(/usr/bin/python3 " + path + " || python3 " + path + ") 2>/dev/null";
  FILE* pipe = popen(cmd.c_str(), "r");
  REQUIRE(pipe != nullptr);
  std::string out;
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, pipe)) out.append(buf, n);
  pclose(pipe);
  std::istringstream lines(out);
  std::vector<double> theirs;
  for (double v; lines >> v;) theirs.push_back(v);
  INFO("scipy output: " << out);
  REQUIRE(theirs.size() == ours.size());
  for (std::size_t i = 0; i < ours.size(); ++i) CHECK(ours[i] == Approx(theirs[i]).epsilon(1e-12));
}
