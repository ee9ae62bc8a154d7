// Where a mesh's float vertices are measured from. Skeleton positions are doubles in world
// coordinates; a mesh stores float32 vertices, whose spacing at UTM eastings and northings
// (1e6-4e6) is 0.125-0.25 m, so a georeferenced tree would snap to a coarse grid. Vertices are
// therefore written relative to a local origin chosen here in double precision, and every
// writer records the origin (glTF: the root node's translation; OBJ, PLY: a comment).
#pragma once

#include "core/skeleton.h"
#include "core/vec3.h"

namespace ramus::mesh {

// Within this distance of the origin a float32 coordinate is off by at most half its spacing,
// 2^-11 m (0.49 mm), which is what "no vertex loses more than 1 mm" allows.
inline constexpr double kFloatMillimetreRange = 16384.0;

// (0, 0, 0) when every node and organ lies within kFloatMillimetreRange of it (grammar trees,
// so their files keep vertices in the grammar's own frame); otherwise the centre of the nodes'
// bounds in x and y and their lowest z, each rounded to a whole unit, so the tree's base sits
// near the local origin and the recorded offset reads cleanly.
Vec3 local_origin(const Skeleton& skeleton);

// The skeleton moved by -origin (nodes and organs); frames, radii and links unchanged.
Skeleton relative_to(const Skeleton& skeleton, const Vec3& origin);

}  // namespace ramus::mesh
