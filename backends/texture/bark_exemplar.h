// The bundled bark exemplar: a licence-clean picture of furrowed bark drawn procedurally, so the
// default tile set (`ramus tiles` without pictures, `ramus build` without --bark) needs no photo.
// Vertical plates of bark separated by dark, wandering furrows, with fine vertical grain and a
// few horizontal cracks; everything is fractal value noise keyed by the seed, so the same seed
// gives the same pixels on every machine.
#pragma once

#include <cstdint>

#include "backends/texture/image.h"

namespace ramus::texture {

struct BarkStyle {
  double furrows = 9;                     // furrows across the picture's width
  double warp = 0.35;                     // how far furrows wander sideways (in furrow spacings)
  double plate[3] = {0.42, 0.34, 0.27};   // colour of the bark plates (sRGB values, 0..1)
  double furrow[3] = {0.13, 0.10, 0.08};  // colour deep in a furrow
};

// A size x size bark picture (size >= 16) that itself tiles.
Image bark_exemplar(int size, std::uint64_t seed, const BarkStyle& style = {});

}  // namespace ramus::texture
