// The colour coding shared by rgb12 (version 2) and rgb14/rgbnir14 (layered version 3): a 7-bit
// mask of the changed bytes (bit 6: not grey), the low and high bytes of red coded as
// differences, green and blue predicted from red's change (Isenburg 2013, section 4.3).
#pragma once

#include <cstdint>

#include "formats/laz/adaptive_models.h"
#include "formats/laz/range_decoder.h"
#include "formats/laz/range_encoder.h"

namespace ramus::laz {

struct RgbModels {
  SymbolModel used{128};
  SymbolModel diff[6] = {SymbolModel(256), SymbolModel(256), SymbolModel(256),
                         SymbolModel(256), SymbolModel(256), SymbolModel(256)};
  void reset() {
    used.reset();
    for (auto& m : diff) m.reset();
  }
};

// Decodes a colour against `last` into `out` (both red, green, blue).
void decode_rgb(RangeDecoder& dec, RgbModels& m, const std::uint16_t last[3], std::uint16_t out[3]);
void encode_rgb(RangeEncoder& enc, RgbModels& m, const std::uint16_t last[3],
                const std::uint16_t rgb[3]);

}  // namespace ramus::laz
