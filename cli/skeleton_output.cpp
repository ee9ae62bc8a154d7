#include "cli/skeleton_output.h"

#include <filesystem>

#include "backends/mesh/gltf_writer.h"
#include "backends/mesh/openmesh_writer.h"
#include "mesh/tree_mesh.h"
#include "cli/command.h"
#include "formats/skeleton_json.h"

namespace ramus::cli {

std::string check_skeleton_output(const std::string& p) {
  const std::string e = std::filesystem::path(p).extension().string();
  return e == ".glb" || e == ".gltf" || e == ".obj" || e == ".ply" || e == ".json"
             ? ""
             : "the output must end in .glb, .gltf, .obj, .ply or .json";
}

void write_skeleton_output(const Skeleton& s, const std::string& path, const std::string& name,
                           mesh::UpAxis up) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".json") return write_skeleton_json(path, s);
  mesh::MeshOptions mo;
  mo.name = name;
  try {
    if (ext == ".glb" || ext == ".gltf") {
      mesh::write_gltf({mesh::build_tree_mesh(s, mo)}, path);
    } else {
      mesh::write_openmesh(mesh::build_tree_mesh(s, mo), path, up);
    }
  } catch (const mesh::MeshError& e) {
    throw UserError(e.what());
  }
}

}  // namespace ramus::cli
