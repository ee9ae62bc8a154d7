// Organ geometry: leaf cards at organ anchors, and the turtle's polygons. Cards: A card of length
// `size` runs along the anchor's heading H from the anchor point, its width along L, so the leaf
// faces U (the turtle's up). Every card gets a front and a back face with opposite normals: engines
// can then keep the leaf material single-sided and still light both sides correctly.
#include <algorithm>
#include <cmath>

#include "mesh/builders.h"
#include "mesh/frames.h"
#include "mesh/polygon_triangulation.h"

namespace ramus::mesh {
namespace {

// Orthonormal (heading, across) from the anchor's frame, repaired if degenerate.
void card_axes(const OrganAnchor& o, Vec3& h, Vec3& l, Vec3& u) {
  h = normalized(o.heading, Vec3{0, 0, 1});
  l = o.left - h * dot(o.left, h);
  l = length(l) > 1e-9 ? normalized(l) : any_perpendicular(h);
  u = cross(h, l);
}

// One two-faced card spanned by `across` (width axis) and `h` (length axis).
void add_card(MeshPart& out, const Vec3& origin, const Vec3& h, const Vec3& across, double len,
              double width, const WindField& wind, float branch, float phase, std::uint32_t node) {
  const Vec3 normal = normalized(cross(h, across));
  for (int face = 0; face < 2; ++face) {
    const std::uint32_t b = std::uint32_t(out.positions.size());
    const Vec3 n = face == 0 ? normal : -normal;
    for (int k = 0; k < 4; ++k) {
      const double u = k & 1, v = k >> 1;
      const Vec3 pos = origin + across * ((u - 0.5) * width) + h * (v * len);
      out.positions.push_back(Vec3f(pos));
      out.normals.push_back(Vec3f(n));
      out.uvs.push_back({float(u), float(v)});
      out.wind.push_back({wind.main_bend(pos.z), branch, phase, float(v)});
      out.skin_node.push_back(node);
    }
    // Corners 0 (u0,v0) 1 (u1,v0) 2 (u0,v1) 3 (u1,v1): (0,2,3) winds about h x across.
    if (face == 0) {
      out.indices.insert(out.indices.end(), {b, b + 2, b + 3, b, b + 3, b + 1});
    } else {
      out.indices.insert(out.indices.end(), {b, b + 3, b + 2, b, b + 1, b + 3});
    }
  }
}

}  // namespace

namespace {

// The wind weights of organ o's vertices: its node's branch bend and its chain's phase.
void organ_wind(const PreparedSkeleton& p, const OrganAnchor& o, const WindField& wind,
                float& branch, float& phase) {
  branch = phase = 0;
  if (o.node == kNoParent) return;
  branch = wind.node_branch[o.node];
  const std::uint32_t c = p.chain_of_node[o.node];
  if (c != kNoChain) phase = wind.chain_phase[c];
}

}  // namespace

bool add_organ_polygon(const Skeleton& s, const PreparedSkeleton& p, std::size_t i,
                       const WindField& wind, MeshPart& out) {
  const OrganAnchor& o = s.organs[i];
  const PolygonTriangles t = triangulate_polygon(o.vertices);
  if (t.indices.empty()) return false;
  float branch = 0, phase = 0;
  organ_wind(p, o, wind, branch, phase);
  for (int face = 0; face < 2; ++face) {
    const std::uint32_t b = std::uint32_t(out.positions.size());
    const Vec3 n = face == 0 ? t.normal : -t.normal;
    for (std::size_t k = 0; k < o.vertices.size(); ++k) {
      const Vec3& v = o.vertices[k];
      out.positions.push_back(Vec3f(v));
      out.normals.push_back(Vec3f(n));
      out.uvs.push_back(t.uvs[k]);
      out.wind.push_back({wind.main_bend(v.z), branch, phase, 0.0f});
      // The polygon sways with the node it grew on, as a leaf card does (wind_rig.h).
      out.skin_node.push_back(o.node);
    }
    for (std::size_t k = 0; k + 2 < t.indices.size(); k += 3) {
      if (face == 0) {
        out.indices.insert(out.indices.end(),
                           {b + t.indices[k], b + t.indices[k + 1], b + t.indices[k + 2]});
      } else {  // the back face winds the other way
        out.indices.insert(out.indices.end(),
                           {b + t.indices[k], b + t.indices[k + 2], b + t.indices[k + 1]});
      }
    }
  }
  return true;
}

bool add_organ_cards(const Skeleton& s, const PreparedSkeleton& p, std::size_t i,
                     const WindField& wind, const MeshOptions& options, double extra_scale,
                     MeshPart& out) {
  const OrganAnchor& o = s.organs[i];
  const double len = o.size * options.leaf_scale * extra_scale;
  if (!(len > 0)) return false;
  Vec3 h, l, u;
  card_axes(o, h, l, u);
  float branch = 0, phase = 0;
  organ_wind(p, o, wind, branch, phase);
  const double width = len * options.leaf_aspect;
  // A leaf on no node (kNoParent, a free organ) stays where it is (wind_rig.h).
  const std::uint32_t node = o.node;
  add_card(out, o.position, h, l, len, width, wind, branch, phase, node);
  if (options.leaf_style == LeafStyle::kCrossed) {
    add_card(out, o.position, h, u, len, width, wind, branch, phase, node);
  }
  return true;
}

}  // namespace ramus::mesh
