// OBJ (+ MTL) and PLY output of a TreeMesh through OpenMesh. OBJ carries positions, normals and
// UVs with the faces grouped by material (`usemtl bark` / `usemtl leaf`, described in the .mtl
// beside it); PLY is binary little-endian with normals, UVs and per-vertex colours (bark brown,
// leaf green). Neither format has a place for the wind weights; use glTF for those.
// Both formats lack an up-axis convention of their own, so the caller chooses one (Blender's OBJ
// importer assumes y up, CloudCompare and the scan tools z up); both files state it and the
// mesh's local origin in a comment ("# up y" / "# origin X Y Z" in OBJ, "comment up y" /
// "comment origin X Y Z" in the PLY header), in the file's own axes: world = origin + vertex.
#pragma once

#include <string>

#include "mesh/tree_mesh.h"
#include "core/up_axis.h"

namespace ramus::texture {
struct BarkTextures;
}

namespace ramus::mesh {

// Writes `path` (.obj, plus <stem>.mtl beside it; or .ply) atomically. Throws MeshError for an
// empty mesh or an unknown extension, WriteError when a file cannot be written. `bark_textures`:
// the bark pictures written beside an OBJ (docs/textures.md); null for the bundled tile set's.
void write_openmesh(const TreeMesh& mesh, const std::string& path, UpAxis up,
                    const texture::BarkTextures* bark_textures = nullptr);

// The MTL text `write_openmesh` puts beside an OBJ named STEM.obj: bark with map_Kd
// STEM_bark.jpg, bump STEM_bark_height.jpg (a height map, as MTL's bump means) and norm
// STEM_bark_normal.jpg (the tangent-space normal map, three.js's MTLLoader reads it); leaf with
// map_Kd and map_d STEM_leaf.png (RGBA: the alpha is the leaf's outline). The pictures are
// written beside the OBJ with it.
std::string obj_material_library(const std::string& stem);

}  // namespace ramus::mesh
