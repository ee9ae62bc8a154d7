// Hand-built branch-structure graphs for the tests of the steps after the centre lines.
#pragma once

#include <cstdint>

#include "reconstruct/bsg/bsg.h"

namespace ramus::test {

// Appends a node at p under `parent` (bsg::kNone for a root) with radius r, weight and mass 1
// and no graph vertex; returns its index.
inline std::uint32_t add_bsg_node(bsg::Bsg& b, const Eigen::Vector3d& p, std::uint32_t parent,
                                  double r) {
  b.pos.push_back(p);
  b.parent.push_back(parent);
  b.vertex.push_back(bsg::kNone);
  b.weight.push_back(1);
  b.radius.push_back(r);
  b.mass.push_back(1);
  return std::uint32_t(b.size() - 1);
}

}  // namespace ramus::test
