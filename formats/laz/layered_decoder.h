// Decoder of layered chunks (compressor 3): the first record raw, the chunk's point count, the
// byte size of every layer, then the layers. Items: point14 v3, then rgb14 or rgbnir14 v3, then
// byte14 v3 (point formats 6-8 with extra bytes); wave packets (formats 9-10) are refused.
#pragma once

#include <memory>
#include <string>

#include "formats/laz/chunk_codecs.h"

namespace ramus::laz {

std::unique_ptr<ChunkCodec> make_layered_decoder(const LaszipVlr& vlr, std::string& why);

}  // namespace ramus::laz
