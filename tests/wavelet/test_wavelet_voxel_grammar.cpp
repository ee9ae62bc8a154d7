// Voxel grammar (III-C) and super-resolution (III-D): infer/wavelet/voxel_grammar.h,
// super_resolution.h.
#include <bit>
#include <catch2/catch.hpp>

#include "infer/wavelet/super_resolution.h"
#include "infer/wavelet/voxel_grammar.h"
#include "wavelet_fractal.h"
#include "wavelet_test_util.h"

using namespace ramus;
using namespace ramus::wavelet;

TEST_CASE("quantizer: mid-tread classes with an exact zero", "[wavelet]") {
  CoefficientQuantizer q = make_quantizer(1.0, 17);
  CHECK(q.zero_class() == 8);
  CHECK(q.quantize(0.0) == 8);
  CHECK(q.quantize(0.125) == 9);
  CHECK(q.quantize(-0.125) == 7);
  CHECK(q.quantize(1.0) == 16);
  CHECK(q.quantize(5.0) == 16);
  CHECK(q.quantize(-5.0) == 0);
  for (int k = 0; k < 17; ++k) CHECK(q.quantize(q.value(k)) == k);  // multiples of 1/8 are exact
  CHECK(q.value(8) == 0.0);
  CHECK_THROWS_AS(make_quantizer(1.0, 16), std::invalid_argument);
  CHECK_THROWS_AS(make_quantizer(1.0, 1), std::invalid_argument);
  CHECK(make_quantizer(0.0, 5).range == 1.0);
}

TEST_CASE("voxel grammar: one observation per parent cell and pair of dyads", "[wavelet]") {
  VoxelGrid g = test::random_grid(4, 11, 0.2);
  for (Decomposition d : {Decomposition::standard, Decomposition::nonstandard}) {
    VoxelGrammar vg = learn_voxel_grammar(haar_forward(g, d));
    // Parents at levels 0..2 of side 1, 2, 4: 73 cells per chain; 7 chains when nonstandard.
    std::uint64_t chains = d == Decomposition::standard ? 1 : 7;
    CHECK(vg.observations() == 73 * chains);
    CHECK(vg.rules.size() > 10);
    for (const VoxelRule& r : vg.rules) {
      auto [first, last] = vg.rules_for(r.subband, r.parent);
      CHECK(&r >= &vg.rules[first]);
      CHECK(&r < &vg.rules[0] + last);
    }
  }
}

TEST_CASE("voxel grammar: a self-similar shape gives deterministic rules", "[wavelet]") {
  VoxelGrid g = test::sierpinski(5);
  VoxelGrammar vg = learn_voxel_grammar(haar_forward(g, Decomposition::nonstandard));
  // Only the xyz subband carries detail (contrast 1 in every occupied cell) and every parent
  // class has exactly one rule: zero -> zeros, one -> ones at the even octants.
  const int zero = vg.quantizer.zero_class(), one = vg.quantizer.quantize(1.0);
  REQUIRE(vg.rules_for(7, one).second - vg.rules_for(7, one).first == 1);
  const VoxelRule& r = vg.rules[vg.rules_for(7, one).first];
  for (int c = 0; c < 8; ++c) {
    CHECK(r.children[c] == (std::popcount(unsigned(c)) % 2 == 0 ? one : zero));
  }
  for (int s = 1; s < 7; ++s) {
    auto [first, last] = vg.rules_for(s, zero);
    REQUIRE(last - first == 1);
    CHECK(vg.rules[first].children ==
          std::array<std::uint8_t, 8>{std::uint8_t(zero), std::uint8_t(zero), std::uint8_t(zero),
                                      std::uint8_t(zero), std::uint8_t(zero), std::uint8_t(zero),
                                      std::uint8_t(zero), std::uint8_t(zero)});
  }
}

TEST_CASE("super-resolution: recovers the next level of a self-similar shape exactly",
          "[wavelet]") {
  for (int levels : {3, 4, 5}) {
    SuperResolution sr = super_resolve(test::sierpinski(levels));
    VoxelGrid truth = test::sierpinski(levels + 1);
    ResolutionComparison c = compare_resolutions(test::sierpinski(levels), sr.grid, truth);
    INFO("levels " << levels);
    CHECK(c.iou_enhanced == 1.0);
    CHECK(c.iou_upsampled == Approx(0.5));  // upsampling fills all 8 octants, the truth 4
    CHECK(c.voxels_enhanced == c.voxels_truth);
  }
}

TEST_CASE("super-resolution: stochastic and reproducible by seed and empty voxels stay empty",
          "[wavelet]") {
  VoxelGrid g = test::random_grid(4, 5, 0.4);
  SuperResolutionOptions o;
  o.seed = 3;
  SuperResolution a = super_resolve(g, o), b = super_resolve(g, o);
  CHECK(a.grid.values == b.grid.values);
  o.seed = 4;
  SuperResolution c = super_resolve(g, o);
  CHECK(a.grid.values != c.grid.values);
  CHECK(a.grid.n == 32);
  CHECK(a.grid.voxel_size == g.voxel_size / 2);
  for (std::size_t z = 0; z < 32; ++z) {
    for (std::size_t y = 0; y < 32; ++y) {
      for (std::size_t x = 0; x < 32; ++x) {
        if (g.at(x / 2, y / 2, z / 2) == 0) REQUIRE(a.grid.at(x, y, z) == 0);
      }
    }
  }
  // The mean of every 2x2x2 block is the input voxel: the synthetic details only redistribute.
  auto means = approximation_levels(a.grid);
  for (std::size_t i = 0; i < g.size(); ++i) {
    REQUIRE(means[4].values[i] == Approx(g.values[i]).margin(1e-12));
  }
  CHECK_THROWS_AS(super_resolve(VoxelGrid(1)), std::invalid_argument);
}

TEST_CASE("voxel grammar: a raw (non-relative) grammar and a borrowed class", "[wavelet]") {
  VoxelGrid g = test::random_grid(4, 21, 0.3);
  VoxelGrammarOptions o;
  o.relative = false;
  o.classes = 9;
  VoxelGrammar vg = learn_voxel_grammar(haar_forward(g, Decomposition::nonstandard), o);
  CHECK_FALSE(vg.relative);
  CHECK(vg.quantizer.classes == 9);
  // Every class of every subband resolves to some rules (borrowed from the nearest class).
  for (int s = 1; s <= 7; ++s) {
    for (int p = 0; p < 9; ++p) {
      auto [first, last] = vg.rules_for(s, p);
      CHECK(first < last);
    }
  }
  Rng rng(1);
  CHECK(pick_rule(vg, 7, 4, rng) != nullptr);
  CHECK(pick_rule(vg, 0, 4, rng) == nullptr);
}
