// Decoder of layered chunks (compressor 3): the first record raw, the chunk's point count, the
// byte size of every layer, then the layers. Items: point14 v3 (point formats 6, and 7-10 are
// not decoded yet: their rgb14/nir14/wavepacket14 layers are refused with a clear message).
#pragma once

#include <memory>
#include <string>

#include "formats/laz/chunk_codecs.h"

namespace ramus::laz {

std::unique_ptr<ChunkCodec> make_layered_decoder(const LaszipVlr& vlr, std::string& why);

}  // namespace ramus::laz
