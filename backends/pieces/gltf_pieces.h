// glTF 2.0 output of an assembled pieces forest (docs/pieces.md, "Outputs"), in one of three
// encodings:
//  - canonical: one shared mesh per piece type (piece space, piece-local JOINTS_0); one
//    bone-node hierarchy per tree under a root node; one skin per placed piece whose joints are
//    the window of bone nodes starting at the piece's bone offset; one shared inverse-bind-matrix
//    accessor per piece type; the skinned nodes at the scene root without transforms; the bone
//    offset and the tile slices of every instance in its node's extras;
//  - flatten: every piece of every tree merged into one mesh with one skin (one draw call);
//  - gpu-instancing: per piece type one node with EXT_mesh_gpu_instancing (TRANSLATION,
//    ROTATION, SCALE of each instance's root joint plus the custom _BONE_OFFSET and _TILE
//    attributes), no skins, the extension in extensionsUsed only.
// An optional wind clip (canonical and flatten) becomes a looping glTF animation of the bones.
#pragma once

#include <memory>
#include <string>

#include "backends/mesh/gltf_container.h"
#include "backends/pieces/output_layout.h"
#include "backends/pieces/pieces.h"
#include "backends/texture/tile_atlas.h"

namespace ramus::pieces {

enum class GltfEncoding { kCanonical, kFlatten, kGpuInstancing };

struct PiecesGltfOptions {
  GltfEncoding encoding = GltfEncoding::kCanonical;
  std::size_t lod = 0;  // index into PieceType::lods written as the piece meshes
  bool wind = false;    // add the wind clip of every tree (WindOptions seeded per tree)
  WindOptions wind_options;
  std::string name = "pieces";  // the scene and the root node
  std::uint64_t seed = 1;       // the bark tiles (bark_tiles.h) and the leaf cards (foliage.h)
  // The bark's tile set as a padded atlas (texture/bark_maps.h bark_atlas); null: the bundled set.
  std::shared_ptr<const texture::TileAtlas> bark;
};

using PiecesGltfBytes = mesh::GltfBytes;  // a GLB, or a .gltf's JSON and its .bin

// The file's bytes. Same input, same bytes. Throws PiecesError for a forest without pieces, an
// unknown LOD, more than 65535 bones in a flattened file or a buffer beyond glTF's limits.
PiecesGltfBytes encode_pieces_gltf(const PieceSet& set, const Forest& forest,
                                   const PiecesGltfOptions& options, bool binary,
                                   const std::string& bin_uri = "");

// Writes `path` (.glb, or .gltf with its .bin beside it) atomically.
void write_pieces_gltf(const PieceSet& set, const Forest& forest, const PiecesGltfOptions& options,
                       const std::string& path);

}  // namespace ramus::pieces
