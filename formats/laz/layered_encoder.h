// Encoder of layered chunks (compressor 3) for point format 6 records (point14 v3), the inverse
// of layered_decoder.h: every layer is range coded into its own buffer and a chunk is written
// as the first record raw, the point count, the layer sizes and the layers. A layer whose
// field never changes within the chunk is left empty, as the format allows.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ramus::laz {

// Appends one chunk of `n` point format 6 records (30 bytes each) to `out`.
void encode_point14_chunk(const std::uint8_t* records, std::size_t n,
                          std::vector<std::uint8_t>& out);

}  // namespace ramus::laz
