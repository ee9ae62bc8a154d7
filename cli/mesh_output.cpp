#include "cli/mesh_output.h"

#include <filesystem>

namespace ramus::cli {

void add_up_option(CLI::App* sub, std::string& up) {
  sub->add_option("--up", up,
                  "up axis of an OBJ or PLY mesh: y or z (default: y for .obj, z for .ply; glTF "
                  "is always y up)")
      ->check(CLI::IsMember({"y", "z"}));
}

mesh::UpAxis mesh_up_axis(const std::string& up, const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext != ".obj" && ext != ".ply") {
    if (!up.empty()) {
      throw UserError("--up applies to .obj and .ply meshes only" +
                      std::string(ext == ".glb" || ext == ".gltf" ? " (glTF is always y up)" : ""));
    }
    return mesh::UpAxis::kY;
  }
  if (up.empty()) return ext == ".obj" ? mesh::UpAxis::kY : mesh::UpAxis::kZ;
  return up == "y" ? mesh::UpAxis::kY : mesh::UpAxis::kZ;
}

std::string lod_file_path(const std::string& path, int k) {
  const std::filesystem::path p(path);
  std::filesystem::path out = p.parent_path() / p.stem();
  out += "_LOD" + std::to_string(k) + p.extension().string();
  return out.string();
}

}  // namespace ramus::cli
