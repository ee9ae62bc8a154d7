// Reading a mesh file back into a TreeMesh, so `ramus preview` can show what `ramus build` and
// `ramus reconstruct` wrote (and meshes from elsewhere): glTF (.glb, .gltf; gltf_reader.cpp,
// the one reader that includes tinygltf) and OBJ or PLY (openmesh_reader.cpp, OpenMesh).
// The result is in ramus's world, z up, whatever the file's axes: glTF is y up (spec 3.4) and
// turns back by the inverse of up_axis.h; OBJ and PLY honour the `up y|z` comment the writers
// put in them (default y for OBJ, z for PLY, the writers' defaults). Node transforms, including
// the root translation of a georeferenced file, are applied in double precision, and the
// vertices are kept relative to a local origin (TreeMesh::origin) so they lose nothing in float.
// Triangles are split into bark and leaves by material (glTF: a material named "leaf" or not
// opaque; OBJ/PLY: a colour greener than red), without UVs: the picture draws them whole.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "mesh/tree_mesh.h"

namespace ramus::mesh {

// By the extension (.glb .gltf .obj .ply, any case). Throws MeshError naming the file for
// anything it cannot read or a mesh without triangles.
TreeMesh read_mesh_file(const std::string& path);

TreeMesh read_gltf_mesh(const std::string& path);
TreeMesh read_openmesh_mesh(const std::string& path);

// Collects triangles in world coordinates (double, z up) and makes the TreeMesh: one vertex per
// triangle corner (normals from the file when it has them, else the face's).
class ReadMeshBuilder {
 public:
  explicit ReadMeshBuilder(std::string path) : path_(std::move(path)) {}
  // `normals` may be null (flat shading from the face). Throws MeshError ("<path>: ...") for a
  // non-finite corner.
  void add(bool leaf, const std::array<Vec3, 3>& corners, const std::array<Vec3, 3>* normals);
  // Throws MeshError when no triangle was added.
  TreeMesh finish() const;

 private:
  std::string path_;  // for messages and the mesh's name
  struct Corner {
    Vec3 position, normal;
  };
  std::vector<Corner> bark_, leaves_;  // three per triangle
};

}  // namespace ramus::mesh
