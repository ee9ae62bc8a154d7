// Bark tile sets (backends/texture/tile_set.h, Burkus et al. 5.2): the minimum-error cut is the
// cheapest connected path; tiles whose touching edges share a colour join without a seam (the
// issue's acceptance: the mean colour difference across every shared edge is at most the mean
// difference between adjacent pixel columns inside the tiles), on the bundled set and on a set
// from two other pictures; tiles whose edges do not match show a seam the measure sees; the same
// seed gives the same pixels.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>

#include "backends/texture/bark_exemplar.h"
#include "backends/texture/min_error_cut.h"
#include "backends/texture/tile_set.h"
#include "core/rng.h"

using namespace ramus;
using namespace ramus::texture;

namespace {

double pixel_difference(const std::uint8_t* a, const std::uint8_t* b) {
  return (std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2])) / 3.0;
}

// Mean difference between horizontally adjacent pixels inside the tiles.
double inside_column_difference(const TileSet& set) {
  double sum = 0;
  std::size_t n = 0;
  for (int id = 0; id < set.count(); ++id) {
    const Image t = set.tile_image(id);
    for (int y = 0; y < t.height; ++y) {
      for (int x = 0; x + 1 < t.width; ++x, ++n)
        sum += pixel_difference(t.at(x, y), t.at(x + 1, y));
    }
  }
  return sum / double(n);
}

// Mean difference across the edge where `a` lies left of `b` (or above it).
double across(const Image& a, const Image& b, bool side_by_side) {
  double sum = 0;
  const int t = a.width;
  for (int i = 0; i < t; ++i) {
    sum += side_by_side ? pixel_difference(a.at(t - 1, i), b.at(0, i))
                        : pixel_difference(a.at(i, t - 1), b.at(i, 0));
  }
  return sum / t;
}

struct Joins {
  double worst_matching = 0;    // the largest over all pairs that may touch
  double mean_mismatching = 0;  // over pairs whose edge colours differ
};

Joins measure_joins(const TileSet& set) {
  Joins j;
  double mismatch_sum = 0;
  int mismatches = 0;
  std::vector<Image> tiles;
  for (int id = 0; id < set.count(); ++id) tiles.push_back(set.tile_image(id));
  for (int a = 0; a < set.count(); ++a) {
    for (int b = 0; b < set.count(); ++b) {
      const TileEdges ea = set.edges_of(a), eb = set.edges_of(b);
      for (bool side : {true, false}) {
        const double d = across(tiles[std::size_t(a)], tiles[std::size_t(b)], side);
        const bool match = side ? ea.east == eb.west : ea.south == eb.north;
        if (match) {
          j.worst_matching = std::max(j.worst_matching, d);
        } else {
          mismatch_sum += d;
          ++mismatches;
        }
      }
    }
  }
  j.mean_mismatching = mismatches ? mismatch_sum / mismatches : 0;
  return j;
}

// A second kind of picture, unlike bark: soft coloured blobs over a noisy ground, like lichen.
Image blob_picture(int size, std::uint64_t seed) {
  Image img(size, size);
  Rng rng(seed);
  std::vector<std::array<double, 6>> blobs;
  for (int i = 0; i < 120; ++i) {
    blobs.push_back({rng.uniform(0, size), rng.uniform(0, size), rng.uniform(6, 30),
                     rng.uniform(0.3, 0.9), rng.uniform(0.4, 0.8), rng.uniform(0.2, 0.5)});
  }
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      double c[3] = {0.3, 0.32, 0.28};
      for (const auto& b : blobs) {
        const double d2 = (x - b[0]) * (x - b[0]) + (y - b[1]) * (y - b[1]);
        const double w = std::exp(-d2 / (2 * b[2] * b[2]));
        for (int k = 0; k < 3; ++k) c[k] += (b[3 + k] - c[k]) * w;
      }
      const double grain = double(mix64(seed ^ std::uint64_t(y * size + x)) >> 11) * 0x1.0p-53;
      for (int k = 0; k < 3; ++k) {
        img.at(x, y)[k] = std::uint8_t(std::clamp(255 * (c[k] + 0.06 * (grain - 0.5)), 0.0, 255.0));
      }
    }
  }
  return img;
}

}  // namespace

TEST_CASE("the minimum-error cut follows the cheapest connected path", "[texture]") {
  // A band 6 deep and 8 long whose cheap valley steps from depth 1 to depth 4.
  const int length = 8, depth = 6;
  const int valley[length] = {1, 1, 2, 3, 4, 4, 4, 4};
  std::vector<double> error(std::size_t(length) * depth, 10.0);
  for (int i = 0; i < length; ++i) error[std::size_t(i) * depth + valley[i]] = 0;
  std::vector<int> cut = min_error_cut(error, length, depth, 0, depth);
  for (int i = 0; i < length; ++i) CHECK(cut[std::size_t(i)] == valley[i]);
  // Restricted to [2, 6) the cut cannot reach the valley at depth 1 and stays connected.
  cut = min_error_cut(error, length, depth, 2, depth);
  for (int i = 0; i < length; ++i) {
    CHECK(cut[std::size_t(i)] >= 2);
    if (i > 0) CHECK(std::abs(cut[std::size_t(i)] - cut[std::size_t(i - 1)]) <= 1);
  }
  CHECK(cut[3] == 3);
  CHECK_THROWS(min_error_cut(error, length, depth, 3, 3));
}

TEST_CASE("the bundled tile set joins without seams where edge colours match", "[texture]") {
  const TileSet set = bundled_tile_set();
  REQUIRE(set.count() == 16);
  REQUIRE(set.atlas.width == 1024);
  const double inside = inside_column_difference(set);
  const Joins j = measure_joins(set);
  std::printf("bundled set: inside columns %.3f, worst matching join %.3f, mismatching %.3f\n",
              inside, j.worst_matching, j.mean_mismatching);
  CHECK(j.worst_matching <= inside);
  // The measure sees a seam where the colours differ, so the check above can fail.
  CHECK(j.mean_mismatching > inside);
}

TEST_CASE("a tile set from two other pictures joins without seams", "[texture]") {
  BarkStyle pale;
  pale.furrows = 5;
  pale.plate[0] = 0.62, pale.plate[1] = 0.6, pale.plate[2] = 0.55;
  const std::vector<Image> pictures = {bark_exemplar(384, 7, pale), blob_picture(384, 11)};
  TileSetOptions o;
  o.tile = 128;
  o.seed = 5;
  const TileSet set = build_tile_set(pictures, o);
  const double inside = inside_column_difference(set);
  const Joins j = measure_joins(set);
  std::printf("two pictures: inside columns %.3f, worst matching join %.3f, mismatching %.3f\n",
              inside, j.worst_matching, j.mean_mismatching);
  CHECK(j.worst_matching <= inside);
  CHECK(j.mean_mismatching > inside);
}

TEST_CASE("tile sets are deterministic for a seed and refuse bad options", "[texture]") {
  const std::vector<Image> pictures = {bark_exemplar(160, 3)};
  TileSetOptions o;
  o.tile = 64;
  o.seed = 9;
  const TileSet a = build_tile_set(pictures, o), b = build_tile_set(pictures, o);
  CHECK(a.atlas.rgb == b.atlas.rgb);
  o.seed = 10;
  CHECK(build_tile_set(pictures, o).atlas.rgb != a.atlas.rgb);
  CHECK(bark_exemplar(64, 2).rgb == bark_exemplar(64, 2).rgb);
  o.edges = 3;
  CHECK_THROWS_AS(build_tile_set(pictures, o), std::invalid_argument);
  o.edges = 2;
  o.tile = 100;
  CHECK_THROWS_AS(build_tile_set(pictures, o), std::invalid_argument);
  o.tile = 256;  // larger than the 160-pixel exemplar
  CHECK_THROWS_AS(build_tile_set(pictures, o), std::invalid_argument);
  CHECK_THROWS_AS(build_tile_set({}, TileSetOptions{}), std::invalid_argument);
}
