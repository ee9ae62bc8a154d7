// Encoder of layered chunks (compressor 3) for point formats 6-8 (point14 v3, then rgb14 or
// rgbnir14 v3, then byte14 v3 for extra bytes), the inverse of layered_decoder.h: every layer is
// range coded into its own buffer and a chunk is written as the first record raw, the point count,
// the layer sizes and the layers. A layer whose field never changes within the chunk is left empty,
// as the format allows.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "formats/laz/laszip_vlr.h"

namespace ramus::laz {

// Whether `items` are point14 v3 followed by rgb14, rgbnir14 or byte14 v3 items only.
bool layered_items_supported(const std::vector<Item>& items);

// Appends one chunk of `n` records made of `items` (layered_items_supported) to `out`.
void encode_layered_chunk(const std::vector<Item>& items, const std::uint8_t* records,
                          std::size_t n, std::vector<std::uint8_t>& out);

}  // namespace ramus::laz
