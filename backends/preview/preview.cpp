#include "backends/preview/preview.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "backends/mesh/leaf_shape.h"
#include "backends/preview/picture_file.h"
#include "backends/preview/png.h"
#include "backends/preview/view.h"

namespace ramus::preview {
void check_preview_options(const PreviewOptions& o) {
  if (o.width < 16 || o.height < 16 || o.width > 8192 || o.height > 8192) {
    throw std::invalid_argument("preview size must be between 16x16 and 8192x8192");
  }
  if (o.supersample < 1 || o.supersample > 4) {
    throw std::invalid_argument("supersampling must be 1..4");
  }
}

void draw_view_divider(std::vector<std::uint8_t>& rgb, const PreviewOptions& o) {
  for (int y = 0; y < o.height; ++y) {
    std::uint8_t* p = &rgb[(std::size_t(y) * o.width + o.width / 2) * 3];
    p[0] = p[1] = p[2] = 205;
  }
}

namespace {

// `surface`: the polygon organs, drawn whole in the leaf colour (their UVs are planar, not the
// card's leaf mask).
void draw_part(Raster& raster, const View& view, const mesh::MeshPart& part, bool leaf,
               const PreviewOptions& o, bool surface = false) {
  const int f = o.supersample;
  // Leaf cards of a grown tree carry the card UVs the leaf mask is drawn in; leaves read from a
  // file without them are drawn whole.
  const bool masked = leaf && part.uvs.size() == part.positions.size();
  leaf = leaf || surface;
  for (std::size_t t = 0; t + 2 < part.indices.size(); t += 3) {
    const std::uint32_t i0 = part.indices[t], i1 = part.indices[t + 1], i2 = part.indices[t + 2];
    const auto& p = part.positions;
    const bool front = view.faces_viewer(p[i0], p[i1], p[i2]);
    if (!front && o.cull_back_faces) continue;  // back faces: hidden or doubled
    const float side = front ? 1.0f : -1.0f;    // two-sided: light the face the viewer sees
    std::array<Vec3f, 3> v{view.project(p[i0]), view.project(p[i1]), view.project(p[i2])};
    for (Vec3f& q : v) {
      q.x *= float(f);
      q.y *= float(f);
    }
    raster.triangle(v, [&](float b0, float b1, float b2, Rgb& out) {
      const Vec3f n =
          (part.normals[i0] * b0 + part.normals[i1] * b1 + part.normals[i2] * b2) * side;
      if (masked) {
        const float u = part.uvs[i0][0] * b0 + part.uvs[i1][0] * b1 + part.uvs[i2][0] * b2;
        const float w = part.uvs[i0][1] * b0 + part.uvs[i1][1] * b1 + part.uvs[i2][1] * b2;
        if (!mesh::leaf_inside(u, w)) return false;  // the same alpha mask as the glTF texture
        out = shade_leaf(view, n);
      } else if (leaf) {
        out = shade_leaf(view, n);
      } else {
        out = shade_bark(view, n);
      }
      return true;
    });
  }
}

}  // namespace

std::vector<std::uint8_t> render_rgb(const mesh::TreeMesh& tree, const PreviewOptions& o) {
  check_preview_options(o);
  const int f = o.supersample;
  Raster raster(o.width * f, o.height * f, kBackground);
  for (const View& view : make_views(tree, o.width, o.height)) {
    draw_part(raster, view, tree.bark, false, o);
    draw_part(raster, view, tree.leaves, true, o);
    draw_part(raster, view, tree.surfaces, false, o, true);
  }
  auto rgb = raster.resolve(f);
  draw_view_divider(rgb, o);
  return rgb;
}

std::string render_png(const mesh::TreeMesh& tree, const PreviewOptions& o) {
  const auto rgb = render_rgb(tree, o);
  return encode_png(rgb.data(), o.width, o.height, 3);
}

void write_preview(const mesh::TreeMesh& tree, const std::string& path, const PreviewOptions& o) {
  write_picture(
      path, [&] { return render_png(tree, o); }, [&] { return render_svg(tree, o); });
}

}  // namespace ramus::preview
