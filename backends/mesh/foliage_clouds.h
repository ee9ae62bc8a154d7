// Leaf clouds: the leaf cards of a tree grouped into a few spheres, the billboards of 2.5D
// foliage impostors (Burkus, Karpati & Szecsi, section 6: "camera-facing billboards render leaf
// clouds", re-rendered per view with depth). The glTF writer records them as data
// ({"ramus_foliage": {"clouds": [{"centre", "radius"}]}} on the scene's root node,
// docs/textures.md) and `ramus view` draws them (cli/view_impostors.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/tree_mesh.h"

namespace ramus::mesh {

struct FoliageCloud {
  Vec3 centre;    // the mesh's frame (z up, relative to TreeMesh::origin)
  double radius;  // every corner of the cloud's leaf cards lies within it
};

// At most this many clouds per tree: each is one billboard and one offscreen picture.
inline constexpr int kMaxFoliageClouds = 32;

// How many clouds `cards` leaf cards make: about sqrt(cards) (clouds of as many leaves as there
// are clouds), 1..kMaxFoliageClouds; 0 without leaves.
int foliage_cloud_count(std::size_t cards);

// The clouds of a leaf part (TreeMesh::leaves: 4 vertices per card face): k-means over the
// centres of the card faces (k-means++ seeding from ramus::Rng(seed), Lloyd iterations until no
// face changes cloud), each cloud's radius the farthest corner of its faces. Deterministic for
// the part and seed; empty for a part without leaves.
std::vector<FoliageCloud> foliage_clouds(const MeshPart& leaves, std::uint64_t seed = 0);

}  // namespace ramus::mesh
