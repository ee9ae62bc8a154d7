// The wind skin of a tree mesh (`ramus build --wind`): joints along the branch chains that a
// looping animation sways, and for every skeleton node the two joints its vertices blend between.
// The weights are the ones `_WIND` holds: along a chain a vertex blends between the joints before
// and after it by its arc fraction, the same fraction `_WIND.y` (branch) carries, so the joints
// bend a branch progressively from its base to its tip; the joint angles add up along the chain
// hierarchy, so the sway grows toward the tips while the trunk's base joint never moves.
// Built by make_wind_rig (builders.h); written as a glTF skin and animation by gltf_writer.cpp.
#pragma once

#include <cstdint>
#include <vector>

#include "core/vec3.h"

namespace ramus::mesh {

inline constexpr std::uint32_t kNoJoint = 0xffffffffu;

struct WindJoint {
  Vec3 position;                    // rest position in the mesh's frame (z up, local origin)
  std::uint32_t parent = kNoJoint;  // parents come before children
  Vec3 axis{0, 1, 0};               // unit rotation axis (the rest pose has no rotation)
  double amplitude = 0;             // peak angle in radians; 0: the joint does not move
  double phase = 0;                 // in periods, [0, 1)
  int cycles = 1;                   // swings per period (whole, so the clip loops)
};

// Vertices of a node follow joint a with weight 1 - t and joint b with weight t.
struct JointBinding {
  std::uint32_t a = 0, b = 0;
  float t = 0;
};

struct WindRig {
  std::vector<WindJoint> joints;           // joint 0: the base of the first trunk, fixed
  std::vector<JointBinding> node_binding;  // per skeleton node
  double period = 4.0;                     // seconds; the clip loops after one period

  bool empty() const { return joints.empty(); }
  std::size_t animated_joints() const {
    std::size_t n = 0;
    for (const WindJoint& j : joints) n += j.amplitude != 0;
    return n;
  }
  // The binding of a vertex's skin node (kNoParent: the fixed root joint).
  JointBinding binding(std::uint32_t node) const {
    return node < node_binding.size() ? node_binding[node] : JointBinding{};
  }
  // Angle of joint j about its axis at `time` seconds: amplitude * sin(2 pi (cycles t / period +
  // phase)); the trunk has phase 0, so at a quarter period it leans furthest.
  double angle(std::size_t j, double time) const;
};

struct WindRigOptions {
  int max_joints = 128;  // the budget; thinner and shorter chains ride on their parent's joints
  double period = 4.0;   // seconds (>= 2: a tree sways slowly)
};

}  // namespace ramus::mesh
