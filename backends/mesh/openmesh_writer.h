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

#include "backends/mesh/tree_mesh.h"
#include "backends/mesh/up_axis.h"

namespace ramus::mesh {

// Writes `path` (.obj, plus <stem>.mtl beside it; or .ply) atomically. Throws MeshError for an
// empty mesh or an unknown extension, WriteError when a file cannot be written.
void write_openmesh(const TreeMesh& mesh, const std::string& path, UpAxis up);

// The MTL text `write_openmesh` puts beside an OBJ.
std::string obj_material_library();

}  // namespace ramus::mesh
