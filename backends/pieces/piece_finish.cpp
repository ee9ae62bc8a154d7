// The steps every piece type shares once its base quad mesh exists: the joint hierarchy
// (section 4.3), interior normals, tile types (section 5.1), rim loops and the levels of detail
// (section 4.4).
#include <algorithm>
#include <cmath>

#include "backends/pieces/piece_build.h"

namespace ramus::pieces {

namespace {

void make_joints(PieceType& t) {
  // The root joint sits at the centre of the root rim in its canonical pose (identity); the
  // terminal joint of leaf rim i sits at that rim with the rim's building transform, so a
  // child's root joint attached rigidly to it lands exactly on the rim.
  t.joints.clear();
  Joint root;
  root.name = "root";
  t.joints.push_back(root);
  for (const Rim& r : t.leaves) {
    Joint j;
    j.name = "rim:" + r.name;
    j.parent = 0;
    j.bind_local = r.building;
    j.bind = r.building.matrix();
    j.inverse_bind = r.building.inverse().matrix();
    t.joints.push_back(j);
  }
  t.tube_length = 0;
  for (const Rim& r : t.leaves) t.tube_length = std::max(t.tube_length, length(r.building.t));
}

void interior_normals(PieceMesh& m, const std::vector<char>& fixed) {
  std::vector<Vec3> acc(m.positions.size(), Vec3{0, 0, 0});
  for (const auto& q : m.quads) {
    // The cross product of the diagonals is twice the (vector) area of the quad.
    Vec3 n = cross(m.positions[q[2]] - m.positions[q[0]], m.positions[q[3]] - m.positions[q[1]]);
    for (std::uint32_t v : q) acc[v] += n;
  }
  for (std::size_t v = 0; v < acc.size(); ++v) {
    if (!fixed[v]) m.normals[v] = normalized(acc[v]);
  }
}

void clean_weights(PieceMesh& m) {
  for (std::size_t v = 0; v < m.weights.size(); ++v) {
    auto& w = m.weights[v];
    auto& j = m.joints[v];
    double sum = 0;
    for (int k = 0; k < 4; ++k) {
      if (!(w[k] > 0)) {
        w[k] = 0;
        j[k] = 0;
      }
      sum += w[k];
    }
    for (int k = 0; k < 4; ++k) w[k] = float(w[k] / sum);
    // Used slots first, so a vertex bound to one joint has it in slot 0 with weight 1.
    std::array<std::uint16_t, 4> js{0, 0, 0, 0};
    std::array<float, 4> ws{0, 0, 0, 0};
    for (int k = 0, n = 0; k < 4; ++k) {
      if (w[k] > 0) {
        js[n] = j[k];
        ws[n++] = w[k];
      }
    }
    j = js;
    w = ws;
  }
}

void tile_types(PieceMesh& m) {
  m.quad_tile_type.assign(m.quads.size(), 1);
  m.quad_source.resize(m.quads.size());
  for (std::size_t q = 0; q < m.quads.size(); ++q) {
    m.quad_source[q] = std::uint32_t(q);
    for (std::uint32_t v : m.quads[q]) {
      int terminals = 0;
      for (int k = 0; k < 4; ++k) terminals += (m.weights[v][k] > 0 && m.joints[v][k] != 0);
      if (terminals >= 2) m.quad_tile_type[q] = 2;
    }
  }
}

}  // namespace

PieceType finish_piece(PieceDraft d, const std::vector<int>& lod_segments) {
  PieceType t = std::move(d.type);
  PieceMesh& m = d.mesh;
  m.segments = 1;
  make_joints(t);
  interior_normals(m, d.fixed_normal);
  clean_weights(m);
  tile_types(m);
  m.rim_loops.clear();
  m.rim_loops.emplace_back(t.root.corners.begin(), t.root.corners.end());
  for (const Rim& r : t.leaves) m.rim_loops.emplace_back(r.corners.begin(), r.corners.end());
  t.lods.clear();
  t.lods.push_back(m);
  for (int s : lod_segments) {
    if (s > 1) t.lods.push_back(tessellate(m, s));
  }
  return t;
}

std::uint32_t PieceType::leaf_index(std::string_view rim_name) const {
  for (std::size_t i = 0; i < leaves.size(); ++i) {
    if (leaves[i].name == rim_name) return std::uint32_t(i);
  }
  return kNone;
}

}  // namespace ramus::pieces
