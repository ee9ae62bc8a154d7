// Per-node branching rules of a skeleton: the extraction step of skeleton -> L-system inference.
//
// Thesis draft (seeds/001), section 4.3.1.2, Eq. 4.11: every branch node of a tree skeleton gives
// one parametric rule in spherical-turtle form,
//   N(l, r) -> &(theta_0) ^(phi_0) !(r) F(l) S_0(l * a_0, r * b_0) ... S_n(l * a_n, r * b_n),
// where for child i, theta_i is its angle to the parent branch, phi_i its azimuth around the
// parent, a_i and b_i its length and radius ratios to the parent. A "branch" here is an internode:
// the chain of segments between two branch nodes (nodes with no child or with two or more), so
// nodes with exactly one child are collapsed into their internode. docs/skeleton-inference.md
// defines every quantity precisely; extract_branch_rules implements them.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "core/skeleton.h"
#include "core/vec3.h"

namespace ramus::skeleton_infer {

inline constexpr std::uint32_t kNone = 0xffffffffu;

// A chain of segments from `start` (a root or a branch node) to `end` (a tip or a branch node).
struct Internode {
  std::uint32_t start = kNone;
  std::uint32_t end = kNone;
  std::uint32_t parent = kNone;  // the internode ending at `start`; kNone at a root
  std::uint32_t tree = 0;        // index of the root in Skeleton::roots() order
  double length = 0;             // path length along the chain
  double chord = 0;              // straight distance from start to end (<= length)
  double radius = 0;             // radius of the chain's first node (the branch's base)
  Vec3 direction{0, 0, 1};       // unit chord start -> end (the parent's if the chord is empty)
  std::uint16_t order = 0;       // 0 trunk; a lateral child has its parent's order + 1
  std::uint32_t axis_index = 0;  // position along its axis: 0 where the axis starts
  std::uint32_t depth = 0;       // internodes between it and the root
  bool continuation = false;     // continues its parent's axis (smallest angle among siblings)
};

// Child i of Eq. 4.11.
struct ChildRule {
  double theta = 0;  // degrees in [0, 180]: angle between the parent's and the child's directions
  double phi = 0;    // degrees in [0, 360): azimuth of the child in the parent's levelled frame
  double a = 1;      // child length / parent length
  double b = 1;      // child radius / parent radius
  std::uint32_t internode = kNone;
};

// One rule per internode N: its children at N's end node (none for a tip). Children are stored
// continuation first, then the laterals by increasing azimuth.
struct NodeRule {
  std::uint32_t internode = kNone;
  std::uint32_t child_begin = 0, child_count = 0;  // into BranchRules::children
};

struct BranchRules {
  std::vector<Internode> internodes;
  std::vector<NodeRule> rules;  // rules[i].internode == i
  std::vector<ChildRule> children;
  std::vector<std::uint32_t> tree_first;  // first internode of every tree with at least one segment
  std::vector<double> tree_length;        // total internode length of each of those trees

  const ChildRule* begin(const NodeRule& r) const { return children.data() + r.child_begin; }
  const ChildRule* end(const NodeRule& r) const {
    return children.data() + r.child_begin + r.child_count;
  }
};

// Thrown for a skeleton that is not a valid forest (Skeleton::validate's message).
struct ExtractError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The parent's levelled frame used for azimuths: H = direction, L = V x H / |V x H| (V = +z, the
// turtle's `$`), U = H x L. For a vertical H, L is the turtle's initial left (-1, 0, 0).
void levelled_frame(const Vec3& heading, Vec3& left, Vec3& up);

// Angle (degrees, [0, 180]) and azimuth (degrees, [0, 360)) of direction `d` seen from a parent
// with heading H and levelled frame (L, U): the turtle reaches d from (H, L, U) by `/(phi)
// &(theta)`.
void angle_and_azimuth(const Vec3& parent, const Vec3& d, double& theta, double& phi);

// Extracts every internode and its rule. Linear in the number of nodes; no recursion.
BranchRules extract_branch_rules(const Skeleton& skeleton);

}  // namespace ramus::skeleton_infer
