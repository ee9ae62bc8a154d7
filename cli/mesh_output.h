// How the commands that write tree meshes (build, reconstruct, propagate, enhance) choose the up
// axis of OBJ and PLY files and name the files of --lod-files.
#pragma once

#include <string>

#include "core/up_axis.h"
#include "cli/command.h"

namespace ramus::cli {

// --up y|z: the up axis of an OBJ or PLY mesh.
void add_up_option(CLI::App* sub, std::string& up);

// The up axis of a mesh written to `path`: --up when given, else the format's default: y for
// .obj (Blender's importer, Maya, Unity and three.js read OBJ as y up), z for .ply (CloudCompare,
// PDAL and the scans ramus reads and writes are z up, so a reconstructed mesh overlays its
// scan). glTF is always y up (spec 3.4), so --up with a .glb or .gltf (or any other output) is a
// UserError.
mesh::UpAxis mesh_up_axis(const std::string& up, const std::string& path);

// The file of level k for --lod-files: "out/tree.glb" -> "out/tree_LOD2.glb" (a .gltf's .bin,
// an .obj's .mtl follow the same stem).
std::string lod_file_path(const std::string& path, int k);

}  // namespace ramus::cli
