// Skeletal animation of assembled trees (Burkus et al. 2017, section 4.3): bone world matrices
// from the one bone buffer of a tree, linear blend skinning, seeded random poses and a looping
// wind clip. Root joints stay rigid (turning one would open the rim it shares with the parent);
// only terminal joints move, and every vertex of a rim follows exactly one joint, so posed rims
// still coincide.
#include <algorithm>
#include <cmath>

#include "backends/pieces/pieces.h"
#include "core/rng.h"

namespace ramus::pieces {

std::vector<Mat4> bone_world(const Tree& tree, std::span<const Trs> locals) {
  std::vector<Mat4> w(tree.bones.size());
  for (std::size_t i = 0; i < tree.bones.size(); ++i) {
    const Trs& l = i < locals.size() ? locals[i] : tree.bones[i].rest;
    std::uint32_t p = tree.bones[i].parent;
    w[i] = p == kNone ? l.matrix() : w[p] * l.matrix();
  }
  return w;
}

std::vector<Trs> random_pose(const Tree& tree, std::span<const Trs> base, std::uint64_t seed,
                             double max_degrees) {
  std::vector<Trs> pose(base.begin(), base.end());
  pose.resize(tree.bones.size());
  for (std::size_t i = base.size(); i < tree.bones.size(); ++i) pose[i] = tree.bones[i].rest;
  const double max_rad = max_degrees * M_PI / 180;
  for (std::size_t i = 0; i < tree.bones.size(); ++i) {
    if (tree.bones[i].joint == 0) continue;      // root joints are rigid
    Rng rng = Rng::stream(seed, i, 0x706f7365);  // "pose"
    // An axis in the rim's plane (bending, not twisting) and an angle up to max_degrees.
    double az = rng.uniform(0, 2 * M_PI);
    double angle = rng.uniform(-max_rad, max_rad);
    Quat bend = Quat::axis_angle({std::cos(az), std::sin(az), 0}, angle);
    pose[i].r = (pose[i].r * bend).normalized();
  }
  return pose;
}

WindClip wind_clip(const Tree& tree, std::span<const Trs> base, const WindOptions& options) {
  WindClip clip;
  const int keys = std::max(options.keys, 2);
  std::vector<Trs> locals(base.begin(), base.end());
  locals.resize(tree.bones.size());
  for (std::size_t i = base.size(); i < tree.bones.size(); ++i) locals[i] = tree.bones[i].rest;
  std::vector<Mat4> world = bone_world(tree, locals);
  std::uint32_t max_depth = 0;
  for (const PlacedPiece& p : tree.pieces) max_depth = std::max(max_depth, p.depth);
  Vec3 wind = normalized(Vec3{options.direction.x, options.direction.y, 0}, Vec3{1, 0, 0});
  // Bending away from the wind: about the horizontal axis perpendicular to it.
  Vec3 axis_world = cross(Vec3{0, 0, 1}, wind);
  const double amp = options.max_degrees * M_PI / 180;
  for (int k = 0; k < keys; ++k) {
    double phase = 2 * M_PI * k / (keys - 1);
    clip.times.push_back(options.period * k / (keys - 1));
    std::vector<Quat> rot(tree.bones.size());
    for (std::size_t i = 0; i < tree.bones.size(); ++i) {
      rot[i] = locals[i].r;
      if (tree.bones[i].joint == 0) continue;
      const PlacedPiece& p = tree.pieces[tree.bones[i].piece];
      Rng rng = Rng::stream(options.seed, i, 0x77696e64);  // "wind"
      double offset = rng.uniform(0, 0.6) + 0.35 * p.depth;
      // Thin outer branches sway more than the trunk.
      double a = amp * (0.25 + 0.75 * double(p.depth + 1) / double(max_depth + 1)) *
                 std::sin(phase + offset);
      std::uint32_t parent = tree.bones[i].parent;
      Mat4 parent_inv = parent == kNone ? Mat4{} : world[parent].inverse();
      Vec3 axis_parent = normalized(parent_inv.direction(axis_world), Vec3{1, 0, 0});
      // A rotation in the parent's frame applied before the bone's own local rotation.
      rot[i] = (Quat::axis_angle(axis_parent, a) * locals[i].r).normalized();
    }
    clip.rotations.push_back(std::move(rot));
  }
  // A loop: the last key is exactly the first.
  clip.rotations.back() = clip.rotations.front();
  return clip;
}

SkinnedPiece skin_piece(const PieceSet& set, const Tree& tree, std::span<const Mat4> world,
                        std::uint32_t placed, std::size_t lod) {
  const PlacedPiece& p = tree.pieces[placed];
  const PieceType& t = set.types[p.type];
  const PieceMesh& m = t.lods[std::min(lod, t.lods.size() - 1)];
  std::vector<Mat4> skin(t.joints.size());
  for (std::size_t j = 0; j < t.joints.size(); ++j) {
    skin[j] = world[p.bone_offset + j] * t.joints[j].inverse_bind;
  }
  SkinnedPiece out;
  out.positions.resize(m.positions.size());
  out.normals.resize(m.positions.size());
  for (std::size_t v = 0; v < m.positions.size(); ++v) {
    Mat4 blend;
    blend.m.fill(0);
    int used = 0, single = -1;
    for (int k = 0; k < 4; ++k) {
      double w = m.weights[v][k];
      if (w <= 0) continue;
      ++used;
      single = m.joints[v][k];
      const Mat4& s = skin[m.joints[v][k]];
      for (int e = 0; e < 16; ++e) blend.m[e] += w * s.m[e];
    }
    // A vertex bound to one joint uses that joint's matrix exactly (weights are floats: a sum
    // of 1.0f times the matrix is the matrix, but say so rather than rely on it).
    const Mat4& M = used == 1 ? skin[single] : blend;
    out.positions[v] = M.point(m.positions[v]);
    out.normals[v] = M.normal(m.normals[v]);
  }
  return out;
}

}  // namespace ramus::pieces
