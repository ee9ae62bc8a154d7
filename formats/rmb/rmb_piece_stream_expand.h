// The expansion of a placed-pieces stream (rmb_piece_stream.h) into the pieces instance buffer
// (formats/pieces_instance_buffer.h, docs/instance-buffer.md): every tree's bones composed along
// their parents from the stream's local transforms, their skinning matrices, the instance
// records grouped by piece type and every instance's texture tiles drawn from the tree's seed.
// The runtime runs this (ramus_pieces_expand in runtime/ramus_runtime.h); the pieces back end
// shares its tile draw, so `ramus build --target pieces --instance-buffer` and the expansion of
// the same tree's stream give the same bytes.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "formats/pieces_instance_buffer.h"
#include "formats/rmb/rmb_piece_stream.h"

namespace ramus {

// The texture-array slices of one placed piece (Burkus et al. 2017, section 5.1): per base quad
// one draw from a stream of (seed, placed) -- a type-2 quad (near a fork) draws from the
// tiles_per_type[1] slices after the tiles_per_type[0] type-1 slices. `quads` quads; quad q is
// type 2 when q < tile_type.size() and tile_type[q] == 2.
std::vector<std::uint16_t> draw_piece_tiles(std::size_t quads,
                                            std::span<const std::uint8_t> tile_type,
                                            std::array<std::uint16_t, 2> tiles_per_type,
                                            std::uint64_t seed, std::uint32_t placed);

// The instance buffer's tables. Throws RmbError (offset 0) when the forest is beyond the
// buffer's 32-bit offsets (checked before anything is allocated).
InstanceBufferTables expand_piece_stream(const RmbPieceStream& stream);

// The same as the instance buffer's binary file.
std::string expand_piece_stream_binary(const RmbPieceStream& stream);

}  // namespace ramus
