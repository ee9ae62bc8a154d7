// The leaf outline every consumer agrees on: the alpha mask of the glTF leaf texture, the
// preview rasterizer's alpha test and the SVG leaf polygons all use leaf_inside / leaf_outline,
// so a leaf looks the same in an engine and in `ramus preview`.
//
// Card coordinates: u across the card (0..1, midrib at 0.5), v along it (0 petiole, 1 tip).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace ramus::mesh {

// Half-width of the blade at v (0 outside [0,1]): a short petiole, then an ovate blade.
double leaf_half_width(double v);
inline bool leaf_inside(double u, double v) {
  return v >= 0 && v <= 1 && std::abs(u - 0.5) <= leaf_half_width(v);
}

// Closed outline in card coordinates, `samples` points per side.
std::vector<std::array<double, 2>> leaf_outline(int samples);

// RGBA8 images (row 0 at the top, v = 0 at the bottom) encoded as PNG in memory.
std::string leaf_texture_png(int width, int height);
std::string bark_texture_png(int width, int height);

}  // namespace ramus::mesh
