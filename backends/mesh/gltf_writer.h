// glTF 2.0 output of TreeMeshes (through tinygltf): `.glb` (one binary file) or `.gltf` with its
// buffer in a `.bin` beside it. Layout (docs/mesh.md): y up (the z-up mesh is turned here,
// core/up_axis.h); one buffer; per LOD one mesh "<name>_LODk" with a "bark" and a
// "leaf" primitive; one scene node per tree showing LOD0, translated to the mesh's local origin,
// with the coarser levels as nodes named only by its MSFT_lod extension (screen coverage hints in
// its extras); PBR materials bark (opaque) and leaf (alphaMode MASK); the wind weights as the
// custom VEC4 float attribute `_WIND`; with a wind rig (MeshOptions::wind) a skin along the
// branch chains and the looping animation "wind"; optionally compressed (gltf_compress.h).
#pragma once

#include <string>
#include <vector>

#include "backends/mesh/gltf_compress.h"
#include "backends/mesh/gltf_container.h"
#include "mesh/tree_mesh.h"

namespace ramus::texture {
struct BarkTextures;
}

namespace ramus::mesh {

// `bark` (in the functions below): the bark's base colour and normal map (docs/textures.md);
// null for the bundled tile set's.

// The file's bytes: a GLB container, or (binary == false) the JSON of a .gltf whose buffer uri
// is `bin_uri` and the .bin bytes in `bin`.
GltfBytes encode_gltf(const std::vector<TreeMesh>& lods, bool binary,
                      const std::string& bin_uri = "",
                      GltfCompression compression = GltfCompression::kNone,
                      const texture::BarkTextures* bark = nullptr);

// Writes `path` (.glb or .gltf; for .gltf also <stem>.bin beside it) atomically. Throws MeshError
// for an empty tree or a buffer beyond glTF's limits, WriteError when a file cannot be written.
void write_gltf(const std::vector<TreeMesh>& lods, const std::string& path,
                GltfCompression compression = GltfCompression::kNone,
                const texture::BarkTextures* bark = nullptr);

}  // namespace ramus::mesh
