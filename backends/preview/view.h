// The two orthographic views of the preview and the shading they share (PNG and SVG).
#pragma once

#include <array>

#include "mesh/tree_mesh.h"
#include "backends/preview/raster.h"

namespace ramus::preview {

struct View {
  Vec3 right, up, forward;  // forward points away from the viewer
  double scale = 1;         // pixels per unit
  double cx = 0, cy = 0;    // pixel position of the tree's reference point
  Vec3 ref;                 // the tree's reference point (bottom centre of its bounds)

  // Pixel x right, y down, depth grows away from the viewer.
  Vec3f project(const Vec3f& p) const;
  // Light from the viewer's upper left.
  Vec3 light() const { return normalized(right * -0.45 + up * 0.65 - forward * 0.6); }
  bool faces_viewer(const Vec3f& a, const Vec3f& b, const Vec3f& c) const;
};

// Front and side views of the box [lo, hi] fitted into a picture of w x h pixels.
std::array<View, 2> make_views(const Vec3& lo, const Vec3& hi, int w, int h);
// The same for the bounds of a tree's vertices.
std::array<View, 2> make_views(const mesh::TreeMesh& tree, int w, int h);

inline constexpr Rgb kBackground{0.96f, 0.96f, 0.94f};
// Lambert plus ambient; leaves light from either side (they are thin and translucent).
Rgb shade_bark(const View& v, const Vec3f& normal);
Rgb shade_leaf(const View& v, const Vec3f& normal);

}  // namespace ramus::preview
