// A finished BSG as a ramus::Skeleton: frames, branch orders, radii, and the leaves of 4.3.
#pragma once

#include <cstdint>

#include "core/skeleton.h"
#include "core/vec3.h"
#include "reconstruct/bsg/bsg.h"

namespace ramus::bsg {

struct LeafParams {
  bool enabled = true;
  int min_count = 20, max_count = 50;
  double sphere = 0.1;
  std::uint64_t seed = 1;
  std::uint64_t tree = 0;  // keys the random streams so trees do not share leaves
};

// Positions become world coordinates (offset + pos).
Skeleton to_skeleton(const Bsg& bsg, const Vec3& offset, const LeafParams& leaves);

}  // namespace ramus::bsg
