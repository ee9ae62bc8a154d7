// The 3D Haar transform (infer/wavelet/haar.h; Friedman & Stamos 2013, III-B).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "infer/wavelet/haar.h"
#include "wavelet_test_util.h"

using namespace ramus::wavelet;
using ramus::wavelet::test::random_grid;

namespace {

double max_abs_diff(const VoxelGrid& a, const VoxelGrid& b) {
  double d = 0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a.values[i] - b.values[i]));
  return d;
}

}  // namespace

TEST_CASE("haar: inverse of forward is the identity for both decompositions", "[wavelet]") {
  for (int levels : {0, 1, 2, 3, 5}) {
    for (Decomposition d : {Decomposition::standard, Decomposition::nonstandard}) {
      VoxelGrid g = random_grid(levels, 7 + levels);
      WaveletPyramid p = haar_forward(g, d);
      CHECK(max_abs_diff(haar_inverse(p), g) < 1e-9);
      // The transform is not the identity itself (except for a single voxel).
      if (levels > 0) CHECK(max_abs_diff(p.coefficients, g) > 1e-3);
    }
  }
}

TEST_CASE("haar: averaging and differencing by hand on a 2x2x2 grid", "[wavelet]") {
  VoxelGrid g(1);
  g.at(0, 0, 0) = 1;  // a single occupied voxel
  for (Decomposition d : {Decomposition::standard, Decomposition::nonstandard}) {
    WaveletPyramid p = haar_forward(g, d);
    // Mean 1/8; every detail is +-1/8 with the sign of the voxel's side: (x0 - x1) / 2 per axis.
    for (std::size_t i = 0; i < 8; ++i) CHECK(p.coefficients.values[i] == Approx(0.125));
  }
  g.at(0, 0, 0) = 0;
  g.at(1, 0, 0) = 1;
  WaveletPyramid p = haar_forward(g, Decomposition::nonstandard);
  CHECK(p.coefficients.at(0, 0, 0) == Approx(0.125));
  CHECK(p.coefficients.at(1, 0, 0) == Approx(-0.125));  // differs along x
  CHECK(p.coefficients.at(0, 1, 0) == Approx(0.125));   // same along y
}

TEST_CASE("haar: the scaling coefficient is the mean and a constant grid has no details",
          "[wavelet]") {
  VoxelGrid g(4);
  for (double& v : g.values) v = 0.75;
  for (Decomposition d : {Decomposition::standard, Decomposition::nonstandard}) {
    WaveletPyramid p = haar_forward(g, d);
    CHECK(p.scaling() == Approx(0.75));
    std::size_t nonzero = 0;
    for (std::size_t i = 1; i < p.coefficients.size(); ++i) {
      nonzero += p.coefficients.values[i] != 0;
    }
    CHECK(nonzero == 0);
  }
}

TEST_CASE("haar: diagonal dyads agree between the standard and nonstandard decompositions",
          "[wavelet]") {
  VoxelGrid g = random_grid(4, 99, 0.3);
  WaveletPyramid s = haar_forward(g, Decomposition::standard);
  WaveletPyramid n = haar_forward(g, Decomposition::nonstandard);
  for (int j = 0; j < 4; ++j) {
    CoefficientBlock b = s.dyad(j);
    CHECK(b.offset[0] == (std::size_t(1) << j));
    for (std::size_t k = 0; k < b.size[2]; ++k) {
      for (std::size_t y = 0; y < b.size[1]; ++y) {
        for (std::size_t x = 0; x < b.size[0]; ++x) {
          REQUIRE(s.at(b, x, y, k) == Approx(n.at(b, x, y, k)).margin(1e-12));
        }
      }
    }
  }
  // ...but the off-diagonal blocks do not: the decompositions are different.
  CHECK(max_abs_diff(s.coefficients, n.coefficients) > 1e-3);
}

TEST_CASE("haar: blocks are addressable by level and subband", "[wavelet]") {
  WaveletPyramid p = haar_forward(VoxelGrid(3), Decomposition::nonstandard);
  CoefficientBlock b = p.subband(1, 5);  // differences along x and z at level 1
  CHECK(b.offset == std::array<std::size_t, 3>{2, 0, 2});
  CHECK(b.size == std::array<std::size_t, 3>{2, 2, 2});
  CoefficientBlock sb = p.standard_block(-1, 2, 0);
  CHECK(sb.offset == std::array<std::size_t, 3>{0, 4, 1});
  CHECK(sb.size == std::array<std::size_t, 3>{1, 4, 1});
  CHECK_THROWS_AS(p.subband(3, 7), std::out_of_range);
  CHECK_THROWS_AS(p.subband(0, 0), std::out_of_range);
}

TEST_CASE("haar: approximation levels are the means of the cells", "[wavelet]") {
  VoxelGrid g = random_grid(3, 5);
  auto a = approximation_levels(g);
  REQUIRE(a.size() == 4);
  double sum = 0;
  for (double v : g.values) sum += v;
  CHECK(a[0].values[0] == Approx(sum / 512));
  CHECK(a[0].values[0] == Approx(haar_forward(g, Decomposition::nonstandard).scaling()));
  double block = 0;
  for (int c = 0; c < 8; ++c) block += g.at(2 + (c & 1), 4 + (c >> 1 & 1), 6 + (c >> 2)) / 8;
  CHECK(a[2].at(1, 2, 3) == Approx(block));
}

TEST_CASE("haar: coefficients match PyWavelets after rescaling to the orthonormal Haar",
          "[wavelet][oracle]") {
  std::string python = test::python_with("numpy, pywt");
  if (python.empty()) {
    WARN("skipped: no python3 with numpy and pywt (scripts/install-deps.sh installs python3-pywt)");
    return;
  }
  for (int levels : {1, 3, 4}) {
    VoxelGrid g = random_grid(levels, 1234 + levels);
    std::string in = test::temp_path("haar_in.txt"), out = test::temp_path("haar_out.txt");
    {
      std::ofstream f(in);
      f.precision(17);
      f << g.n << "\n";
      for (double v : g.values) f << v << "\n";
    }
    for (Decomposition d : {Decomposition::standard, Decomposition::nonstandard}) {
      const char* kind = d == Decomposition::standard ? "standard" : "nonstandard";
      std::string cmd =
          python + " " + test::tool("pywt_haar3d.py") + " " + in + " " + out + " " + kind;
      REQUIRE(std::system(cmd.c_str()) == 0);
      std::ifstream f(out);
      WaveletPyramid p = haar_forward(g, d);
      double worst = 0;
      std::size_t read = 0;
      for (std::size_t z = 0; z < g.n; ++z) {
        for (std::size_t y = 0; y < g.n; ++y) {
          for (std::size_t x = 0; x < g.n; ++x) {
            double ortho;
            REQUIRE(f >> ortho);
            ++read;
            double ours = p.coefficients.at(x, y, z) * orthonormal_scale(d, levels, x, y, z);
            worst = std::max(worst, std::abs(ours - ortho));
          }
        }
      }
      CHECK(read == g.size());
      INFO(kind << " at side " << g.n);
      CHECK(worst < 1e-9);
    }
    std::remove(in.c_str());
    std::remove(out.c_str());
  }
}
