// Building piece types (internal to the pieces back end): the built-in parametric kinds, pieces
// read from glTF/OBJ files, and the steps every piece type shares once its base mesh exists.
#pragma once

#include <string>
#include <vector>

#include "backends/pieces/pieces.h"

namespace ramus::pieces {

// Corner k of the canonical root rim (section 4.2) and its vertex normal: the outward normal of
// the cone of slope kRimConeSlope that narrows towards +z (section 4.4).
Vec3 canonical_corner(int k);
Vec3 canonical_corner_normal(int k);
// A point of that cone at height z above the canonical rim, on corner k's generator: the quad
// loop next to a rim lies on it.
Vec3 canonical_collar(int k, double z);

// A base mesh under construction: positions, which normals are fixed (rim vertices), and for
// each vertex its skinning weights.
struct PieceDraft {
  PieceType type;                  // name, kind, rims (with corners into lods[0]) filled in
  PieceMesh mesh;                  // positions, uvs, quads, joints and weights; normals of rims set
  std::vector<char> fixed_normal;  // per vertex: 1 when `mesh.normals` holds the final normal
};

// Fills joints (from the rims), interior normals (area-weighted quad normals), tile types
// (section 5.1: a quad with a vertex bound to two or more terminal joints lies near a fork and
// takes type 2, every other quad type 1), rim loops and the tessellated levels of detail.
PieceType finish_piece(PieceDraft draft, const std::vector<int>& lod_segments);

struct TubeParams {
  double length = 4, taper = 0.85;
};
struct ForkParams {
  double length = 3, angle = 35, taper = 0.8;
};
struct TrifurcationParams {
  double length = 3, angle = 35, taper = 0.75;
  bool planar = false;
};
struct AttachmentParams {
  double length = 4, angle = 50, taper = 0.9, branch = 0.55;
};

PieceDraft draft_tube(const std::string& name, const TubeParams& p);
PieceDraft draft_fork(const std::string& name, const ForkParams& p);
PieceDraft draft_trifurcation(const std::string& name, const TrifurcationParams& p);
PieceDraft draft_attachment(const std::string& name, const AttachmentParams& p);

// A piece from a glTF (.gltf/.glb) or OBJ file whose rims are named (docs/pieces.md). With
// `bytes`, the file's contents are those bytes (a mesh an .rmb embeds) and `path` only names it:
// in errors, and by its extension the format.
PieceDraft draft_mesh_file(const std::string& name, const std::string& path,
                           const std::string* bytes = nullptr);
PieceDraft draft_gltf_file(const std::string& name, const std::string& path,
                           const std::string* bytes = nullptr);
PieceDraft draft_obj_file(const std::string& name, const std::string& path,
                          const std::string* bytes = nullptr);
// Shared by both readers: the quad mesh plus vertex groups named rim:<name>, -> a draft
// (checks every rim is a regular hexagon, derives building transforms, sets weights).
struct RawRim {
  std::string name;
  std::vector<std::uint32_t> vertices;
};
PieceDraft draft_from_raw(const std::string& name, const std::string& path,
                          std::vector<Vec3> positions,
                          std::vector<std::array<std::uint32_t, 4>> quads,
                          std::vector<RawRim> rims);

// Rotation by 60 * twist degrees about +z: one of the six ways a hexagonal root rim fits a rim.
Trs twist_rotation(int twist);
// Appends a placed piece hanging from `leaf` of `parent` (or the root piece, with `placement`)
// and its bones to `tree`; returns its index. Does not touch tree.pose.
std::uint32_t place_piece(const PieceSet& set, Tree& tree, std::uint32_t type, std::uint32_t parent,
                          std::uint32_t leaf, int twist, const Trs& placement,
                          const TileOptions& tiles, std::uint64_t seed);

}  // namespace ramus::pieces
