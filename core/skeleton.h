// Skeleton: the hub type of ramus.
//
// Produced by the turtle (an L-system's derivation), by scan reconstruction and by voxel/MST
// inference; consumed by every back end and by rule extraction. A skeleton is a forest of nodes;
// each node except a root has a parent, and the segment of a node runs from its parent's position
// to its own. Units are the grammar's (metres for scans). z is up.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/vec3.h"

namespace ramus {

inline constexpr std::uint32_t kNoParent = 0xffffffffu;
inline constexpr std::uint32_t kNoSource = 0xffffffffu;

struct SkeletonNode {
  Vec3 position;
  // The turtle frame at this node (ABOP: heading H, left L, up U; orthonormal, H x L = U).
  Vec3 heading{0, 0, 1};
  Vec3 left{-1, 0, 0};
  Vec3 up{0, -1, 0};
  double radius = 0.0;  // branch radius at this node (half the turtle width)
  std::uint32_t parent = kNoParent;
  std::uint16_t order = 0;  // branch order: 0 trunk, +1 per lateral branch
  // Index of the module in the derived string that made this node (kNoSource for scans).
  std::uint32_t source_module = kNoSource;
};

// An organ (leaf, flower, fruit) placed with `~` by the turtle or synthesized by reconstruction.
struct OrganAnchor {
  std::uint32_t node = kNoParent;  // node it hangs from
  Vec3 position;
  Vec3 heading{0, 0, 1};
  Vec3 left{-1, 0, 0};
  Vec3 up{0, -1, 0};
  double size = 1.0;
  std::uint32_t kind = 0;  // organ kind: 0 leaf; the grammar may name others
  // A polygon organ (ABOP 5.2, the turtle's `{ . }`): its outline in skeleton coordinates, three
  // or more vertices in the order recorded, not closed (the last joins the first). Empty for an
  // organ placed with `~`, which back ends draw as a card of length `size` along `heading`.
  std::vector<Vec3> vertices;
};

struct Skeleton {
  std::vector<SkeletonNode> nodes;
  std::vector<OrganAnchor> organs;
  std::vector<std::string> organ_kinds{"leaf"};

  std::size_t size() const { return nodes.size(); }
  bool empty() const { return nodes.empty(); }

  // Adds a node and returns its index.
  std::uint32_t add(const SkeletonNode& n) {
    nodes.push_back(n);
    return std::uint32_t(nodes.size() - 1);
  }

  // Children of every node in compressed form: children of i are
  // child_index[child_begin[i] .. child_begin[i+1]), in node order.
  struct Children {
    std::vector<std::uint32_t> child_begin;
    std::vector<std::uint32_t> child_index;
    std::uint32_t count(std::uint32_t i) const { return child_begin[i + 1] - child_begin[i]; }
    const std::uint32_t* begin(std::uint32_t i) const { return child_index.data() + child_begin[i]; }
    const std::uint32_t* end(std::uint32_t i) const { return child_index.data() + child_begin[i + 1]; }
  };
  Children children() const;

  std::vector<std::uint32_t> roots() const;

  // Checks structural validity: parents in range, no cycles, finite positions and radii,
  // organ nodes in range. Returns an empty string when valid, else what is wrong.
  std::string validate() const;

  // Sum of segment lengths (node to parent).
  double total_length() const;
  // Axis-aligned bounds of node positions; {0,0,0} for an empty skeleton.
  void bounds(Vec3& lo, Vec3& hi) const;
};

}  // namespace ramus
