#include "backends/preview/view.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ramus::preview {

Vec3f View::project(const Vec3f& p) const {
  const Vec3 d = Vec3(p) - ref;
  return Vec3f(Vec3{cx + scale * dot(d, right), cy - scale * dot(d, up), dot(d, forward)});
}

bool View::faces_viewer(const Vec3f& a, const Vec3f& b, const Vec3f& c) const {
  const Vec3 n = cross(Vec3(b) - Vec3(a), Vec3(c) - Vec3(a));
  return dot(n, forward) < 0;
}

std::array<View, 2> make_views(const mesh::TreeMesh& tree, int w, int h) {
  Vec3 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
          std::numeric_limits<double>::max()};
  Vec3 hi = -lo;
  bool any = false;
  for (const mesh::MeshPart* part : {&tree.bark, &tree.leaves, &tree.surfaces}) {
    for (const Vec3f& p : part->positions) {
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], double(p[k]));
        hi[k] = std::max(hi[k], double(p[k]));
      }
      any = true;
    }
  }
  if (!any) lo = hi = Vec3{};
  return make_views(lo, hi, w, h);
}

std::array<View, 2> make_views(const Vec3& lo, const Vec3& hi, int w, int h) {
  const Vec3 size = hi - lo;
  const double margin = 0.06;
  const double half = w / 2.0;
  const double horizontal = std::max({size.x, size.y, 1e-12});
  const double scale = std::min(half * (1 - 2 * margin) / horizontal,
                                h * (1 - 2 * margin) / std::max(size.z, 1e-12));
  std::array<View, 2> v;
  v[0].right = {1, 0, 0};
  v[0].forward = {0, 1, 0};
  v[1].right = {0, 1, 0};
  v[1].forward = {-1, 0, 0};
  for (int i = 0; i < 2; ++i) {
    v[i].up = {0, 0, 1};
    v[i].scale = scale;
    v[i].ref = Vec3{(lo.x + hi.x) / 2, (lo.y + hi.y) / 2, lo.z};
    v[i].cx = half * i + half / 2;
    // Bottom of the tree sits the margin above the bottom edge; short trees stay grounded.
    v[i].cy = h - h * margin - (h * (1 - 2 * margin) - scale * size.z) / 2;
  }
  return v;
}

Rgb shade_bark(const View& v, const Vec3f& n) {
  const double d = std::max(0.0, dot(normalized(Vec3(n)), v.light()));
  const float k = float(0.38 + 0.62 * d);
  return {0.45f * k, 0.32f * k, 0.21f * k};
}

Rgb shade_leaf(const View& v, const Vec3f& n) {
  const double d = std::abs(dot(normalized(Vec3(n)), v.light()));
  const float k = float(0.5 + 0.5 * d);
  return {0.27f * k, 0.56f * k, 0.19f * k};
}

}  // namespace ramus::preview
