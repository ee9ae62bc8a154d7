// The SVG preview: every visible triangle of both views as a filled polygon, painted back to
// front (painter's algorithm, sorted by mean depth); each leaf card face becomes one polygon
// tracing the leaf outline instead of two triangles. A stroke of the fill colour hides the
// hairline seams renderers leave between adjacent polygons.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "backends/mesh/leaf_shape.h"
#include "backends/preview/picture_file.h"
#include "backends/preview/preview.h"
#include "backends/preview/view.h"

namespace ramus::preview {
namespace {

struct Shape {
  double depth;
  std::size_t order;  // tie-breaker: output is deterministic
  Rgb colour;
  std::vector<Vec3f> points;  // projected
};

double mean_depth(const std::vector<Vec3f>& pts) {
  double s = 0;
  for (const Vec3f& p : pts) s += p.z;
  return pts.empty() ? 0 : s / double(pts.size());
}

// Every triangle of `part` as a polygon; `leaf` picks the leaf colour (leaves read from a file
// without card UVs are plain triangles).
void triangle_shapes(const View& view, const mesh::MeshPart& part, bool leaf, bool cull,
                     std::vector<Shape>& out) {
  for (std::size_t t = 0; t + 2 < part.indices.size(); t += 3) {
    const std::uint32_t i[3] = {part.indices[t], part.indices[t + 1], part.indices[t + 2]};
    const auto& p = part.positions;
    const bool front = view.faces_viewer(p[i[0]], p[i[1]], p[i[2]]);
    if (!front && cull) continue;
    Shape s;
    for (std::uint32_t k : i) s.points.push_back(view.project(p[k]));
    const Vec3f n = (part.normals[i[0]] + part.normals[i[1]] + part.normals[i[2]]) *
                    (front ? 1.0f : -1.0f);  // two-sided: the face the viewer sees
    s.colour = leaf ? shade_leaf(view, n) : shade_bark(view, n);
    s.depth = mean_depth(s.points);
    s.order = out.size();
    out.push_back(std::move(s));
  }
}

// Leaf card faces are 4 consecutive vertices with UVs (0,0) (1,0) (0,1) (1,1) (leaf_builder).
void leaf_shapes(const View& view, const mesh::MeshPart& part, std::vector<Shape>& out) {
  static const auto outline = mesh::leaf_outline(6);
  for (std::size_t b = 0; b + 3 < part.positions.size(); b += 4) {
    const auto& p = part.positions;
    if (!view.faces_viewer(p[b], p[b + 2], p[b + 3])) continue;
    const Vec3f du = p[b + 1] - p[b], dv = p[b + 2] - p[b];
    Shape s;
    for (const auto& uv : outline) {
      s.points.push_back(view.project(p[b] + du * float(uv[0]) + dv * float(uv[1])));
    }
    s.colour = shade_leaf(view, part.normals[b]);
    s.depth = mean_depth(s.points);
    s.order = out.size();
    out.push_back(std::move(s));
  }
}

}  // namespace

std::string render_svg(const mesh::TreeMesh& tree, const PreviewOptions& o) {
  check_preview_options(o);
  std::vector<Shape> shapes;
  const auto views = make_views(tree, o.width, o.height);
  const bool cards = tree.leaves.uvs.size() == tree.leaves.positions.size();
  for (const View& v : views) {
    triangle_shapes(v, tree.bark, false, o.cull_back_faces, shapes);
    if (cards) {
      leaf_shapes(v, tree.leaves, shapes);
    } else {
      triangle_shapes(v, tree.leaves, true, o.cull_back_faces, shapes);
    }
    triangle_shapes(v, tree.surfaces, true, o.cull_back_faces, shapes);
  }
  std::sort(shapes.begin(), shapes.end(), [](const Shape& a, const Shape& b) {
    return a.depth != b.depth ? a.depth > b.depth : a.order < b.order;
  });
  std::string svg = svg_open(o.width, o.height);
  char buf[96];
  svg += "<g stroke-width=\"0.5\" stroke-linejoin=\"round\">\n";
  for (const Shape& s : shapes) {
    const std::string c = svg_colour(s.colour);
    svg += "<polygon fill=\"" + c + "\" stroke=\"" + c + "\" points=\"";
    for (std::size_t k = 0; k < s.points.size(); ++k) {
      std::snprintf(buf, sizeof buf, k ? " %.2f,%.2f" : "%.2f,%.2f", s.points[k].x, s.points[k].y);
      svg += buf;
    }
    svg += "\"/>\n";
  }
  svg += "</g>\n</svg>\n";
  return svg;
}

}  // namespace ramus::preview
