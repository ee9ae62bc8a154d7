// contract: ready
// A pieces forest as the placed-pieces stream of an .rmb (formats/rmb/rmb_piece_stream.h,
// docs/binary-format.md section 12): per placed piece its type, parent rim, twist and, where the
// tree is posed, the quantized pose of its joints. Quantizing changes a posed joint's transform
// by at most the stream's rotation quantum, so the back end writes the dequantized transforms
// back into its own forest (quantize_forest_poses) before it writes anything: its glTF, its
// instance buffer and the runtime's expansion of the stream then show the same tree, and the
// instance buffers are equal byte for byte.
#pragma once

#include <cstdint>
#include <span>

#include "backends/pieces/pieces.h"
#include "formats/rmb/rmb_piece_stream.h"

namespace ramus::pieces {

// `tile_seeds[k]`: the seed tree k's tiles were drawn with (assign_tiles). Throws PiecesError
// for a forest the stream cannot carry: a piece type whose joints are not the standard ones,
// bones out of piece order, tiles that are not the seed's draw, a tree without pieces.
RmbPieceStream encode_piece_stream(const PieceSet& set, const Forest& forest,
                                   std::span<const std::uint64_t> tile_seeds,
                                   const TileOptions& tiles = {});

// Encodes the forest and sets every bone's pose to the stream's (rmb_joint_local), the rest
// transforms of bones whose rest was their pose too. Returns the stream.
RmbPieceStream quantize_forest_poses(const PieceSet& set, Forest& forest,
                                     std::span<const std::uint64_t> tile_seeds,
                                     const TileOptions& tiles = {});

}  // namespace ramus::pieces
