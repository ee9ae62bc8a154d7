// PointCloud: what the scan readers in formats/ produce and inference consumes.
//
// Positions are stored in single precision *relative to `offset`*, which the readers choose
// (in double precision) near the cloud's centre before narrowing, so UTM-scale coordinates
// (~1e6 m) keep millimetre resolution. World position of point i = offset + positions[i].
// Optional channels are either empty or have one entry per point.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/vec3.h"

namespace ramus {

struct PointCloud {
  Vec3 offset;                       // double-precision recentring offset
  std::vector<Vec3f> positions;      // relative to offset
  std::vector<Vec3f> normals;        // optional
  std::vector<float> intensity;      // optional
  std::vector<std::uint8_t> classification;  // optional (LAS classes: 2 ground, 5 high vegetation)
  std::optional<Vec3> scanner;       // scanner origin in world coordinates, when the file says
  std::string source;                // file the cloud came from, for messages

  std::size_t size() const { return positions.size(); }
  bool empty() const { return positions.empty(); }
  Vec3 world(std::size_t i) const { return offset + Vec3(positions[i]); }
};

}  // namespace ramus
