// TreeMesh: the triangle mesh of one tree (bark tubes and leaf cards) that every mesh writer, the
// preview and the embeddable runtime take. Built from a Skeleton by build_tree_mesh /
// build_tree_lods (see docs/mesh.md). Geometry only: the pictures a writer puts on it (bark tile
// sets, the leaf mask) stay in backends/ and reach the writers beside the mesh.
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/skeleton.h"
#include "core/vec3.h"
#include "mesh/wind_rig.h"

namespace ramus::mesh {

// Thrown for input that cannot be meshed (non-finite values, broken parent links, a mesh too
// large for 32-bit indices). The message says what and where.
struct MeshError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// One material's triangles with their own vertices. Vertex attributes are parallel arrays.
struct MeshPart {
  std::vector<Vec3f> positions;
  std::vector<Vec3f> normals;
  std::vector<std::array<float, 2>> uvs;
  // Wind weights per vertex (the glTF `_WIND` attribute): x main bend (0 at the base, 1 at the
  // top of the tree), y branch bend (0 where a branch leaves its parent, 1 at its tip; 0 on the
  // trunk), z phase in [0,1) (per branch, so branches do not sway in unison), w flutter (leaves
  // only: 0 at the petiole, 1 at the leaf tip).
  std::vector<std::array<float, 4>> wind;
  // The skeleton node whose motion each vertex follows: a ring's node for bark, the organ's node
  // for leaves (kNoParent for an organ on no node). The wind skin (wind_rig.h) binds vertices to
  // joints through it.
  std::vector<std::uint32_t> skin_node;
  std::vector<std::uint32_t> indices;  // triangles, counter-clockwise seen from outside

  std::size_t vertex_count() const { return positions.size(); }
  std::size_t triangle_count() const { return indices.size() / 3; }
  bool empty() const { return indices.empty(); }
};

struct TreeMesh {
  std::string name;  // e.g. "tree_LOD0"
  MeshPart bark;     // material "bark": opaque
  // Material "leaf": alpha-masked cards. Every card face is 4 consecutive vertices with UVs
  // (0,0) (1,0) (0,1) (1,1) and 2 triangles; each card has a front and a back face.
  MeshPart leaves;
  // Material "surface": the polygon organs (the turtle's `{ . }`, ABOP 5.2), opaque; every
  // polygon is triangulated twice, a front and a back face with opposite normals.
  MeshPart surfaces;
  // World position (double, z up) of the vertices' (0, 0, 0): zero for trees near the origin,
  // a local origin for georeferenced ones (mesh/local_origin.h). World position of a
  // vertex = origin + vertex; writers record it.
  Vec3 origin;
  // The joints and animation of the wind skin (MeshOptions::wind); empty otherwise. Every level
  // of a tree carries the same rig.
  WindRig wind_rig;
  std::size_t triangle_count() const {
    return bark.triangle_count() + leaves.triangle_count() + surfaces.triangle_count();
  }
};

enum class LeafStyle {
  kQuad,     // one card per organ, two faces with opposite normals
  kCrossed,  // two perpendicular cards per organ (reads well from every side), both two-faced
};

struct MeshOptions {
  std::string name = "tree";
  // 0: radii from the skeleton; > 0: the pipe model r_parent^e = sum r_child^e with this e
  // (2: da Vinci's rule as used by Friedman & Stamos; 2.5: Livny et al.'s allometric ratio).
  double pipe_exponent = 0.0;
  // Radii below this are clamped (and counted in MeshReport). 0: 1e-4 of the skeleton's extent.
  double min_radius = 0.0;
  int max_radial_segments = 12;  // for the thickest branch at LOD0
  int min_radial_segments = 3;
  bool caps = true;
  LeafStyle leaf_style = LeafStyle::kQuad;
  double leaf_scale = 1.0;   // leaf length = anchor size * leaf_scale
  double leaf_aspect = 0.5;  // width / length
  int lod_count = 1;         // meshes LOD0 .. LOD(lod_count-1)
  bool wind = false;         // also build the wind skin (TreeMesh::wind_rig, `--wind`)
  WindRigOptions wind_rig;
};

// What meshing had to repair; the CLI prints these as warnings.
struct MeshReport {
  std::size_t clamped_radii = 0;   // zero, negative or tiny radii raised to the minimum
  std::size_t merged_nodes = 0;    // nodes coincident with their parent (zero-length segments)
  std::size_t skipped_chains = 0;  // branch chains of zero length (no tube)
  std::size_t skipped_organs = 0;  // organs of zero or negative size
  bool radii_synthesized = false;  // the skeleton had no radii: the pipe model made them
  double min_radius = 0.0;         // the minimum radius in force
  std::vector<std::string> warnings() const;
};

// Level `lod` (0 = full detail) of the tree. Throws MeshError for input it cannot mesh.
TreeMesh build_tree_mesh(const Skeleton& skeleton, const MeshOptions& options, int lod = 0,
                         MeshReport* report = nullptr);

// LOD0 .. LOD(options.lod_count-1).
std::vector<TreeMesh> build_tree_lods(const Skeleton& skeleton, const MeshOptions& options,
                                      MeshReport* report = nullptr);

}  // namespace ramus::mesh
