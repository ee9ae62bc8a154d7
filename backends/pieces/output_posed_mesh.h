// The posed pieces forest as one triangle mesh (every placed piece skinned on the CPU with the
// trees' current poses, section 4.3), for the preview picture and for comparisons with the mesh
// back end. Rim vertices of adjoining pieces are separate vertices at the same place, so any
// gap at a joint shows in the picture.
#pragma once

#include "mesh/tree_mesh.h"
#include "backends/pieces/pieces.h"

namespace ramus::pieces {

// The bark, quads split into two triangles each, and the leaf cards of the foliage clouds
// (foliage.h, from `leaf_seed` as in the glTF files; each card with its own back face). `lod`
// indexes PieceType::lods. Throws PiecesError for an unknown LOD.
mesh::TreeMesh posed_forest_mesh(const PieceSet& set, const Forest& forest, std::size_t lod = 0,
                                 std::uint64_t leaf_seed = 1);

}  // namespace ramus::pieces
