// Writing reconstructed trees (`ramus reconstruct`, `ramus merge`): skeleton JSON, or a mesh of
// every tree (.glb, .gltf, .obj, .ply). A scan's skeleton is in its world (UTM) coordinates: the
// mesh is built about a local origin that the writers record (docs/mesh.md), and skeleton JSON
// keeps the doubles as they are.
#pragma once

#include <string>

#include "core/up_axis.h"
#include "core/skeleton.h"

namespace ramus::cli {

// The output extensions: .glb, .gltf, .obj, .ply (mesh) or .json; a CLI11 check's message.
std::string check_skeleton_output(const std::string& path);

// `name` names the mesh; `up` is the OBJ/PLY up axis (cli/mesh_output.h). MeshError becomes
// UserError.
void write_skeleton_output(const Skeleton& trees, const std::string& path, const std::string& name,
                           mesh::UpAxis up);

}  // namespace ramus::cli
