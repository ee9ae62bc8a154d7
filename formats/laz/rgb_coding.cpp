#include "formats/laz/rgb_coding.h"

#include "formats/laz/v2_tables.h"

namespace ramus::laz {

void decode_rgb(RangeDecoder& dec, RgbModels& m, const std::uint16_t last[3],
                std::uint16_t out[3]) {
  const std::uint32_t sym = dec.decode_symbol(m.used);
  const std::int32_t p[3] = {last[0], last[1], last[2]};
  std::int32_t c[3];
  c[0] =
      (sym & 1) ? fold_u8(std::int32_t(dec.decode_symbol(m.diff[0])) + (p[0] & 255)) : p[0] & 0xff;
  c[0] |= (sym & 2) ? fold_u8(std::int32_t(dec.decode_symbol(m.diff[1])) + (p[0] >> 8)) << 8
                    : p[0] & 0xff00;
  if (sym & 64) {
    std::int32_t d = (c[0] & 255) - (p[0] & 255);
    c[1] = (sym & 4)
               ? fold_u8(std::int32_t(dec.decode_symbol(m.diff[2])) + clamp_u8(d + (p[1] & 255)))
               : p[1] & 0xff;
    if (sym & 16) {
      d = (d + (c[1] & 255) - (p[1] & 255)) / 2;
      c[2] = fold_u8(std::int32_t(dec.decode_symbol(m.diff[4])) + clamp_u8(d + (p[2] & 255)));
    } else {
      c[2] = p[2] & 0xff;
    }
    d = (c[0] >> 8) - (p[0] >> 8);
    c[1] |= (sym & 8)
                ? fold_u8(std::int32_t(dec.decode_symbol(m.diff[3])) + clamp_u8(d + (p[1] >> 8)))
                      << 8
                : p[1] & 0xff00;
    if (sym & 32) {
      d = (d + (c[1] >> 8) - (p[1] >> 8)) / 2;
      c[2] |= fold_u8(std::int32_t(dec.decode_symbol(m.diff[5])) + clamp_u8(d + (p[2] >> 8))) << 8;
    } else {
      c[2] |= p[2] & 0xff00;
    }
  } else {
    c[1] = c[2] = c[0];  // grey
  }
  for (int i = 0; i < 3; ++i) out[i] = std::uint16_t(c[i]);
}

void encode_rgb(RangeEncoder& enc, RgbModels& m, const std::uint16_t last[3],
                const std::uint16_t rgb[3]) {
  const std::int32_t c[3] = {rgb[0], rgb[1], rgb[2]}, p[3] = {last[0], last[1], last[2]};
  std::uint32_t sym = 0;
  for (int i = 0; i < 3; ++i) {
    sym |= std::uint32_t((p[i] & 0xff) != (c[i] & 0xff)) << (2 * i);
    sym |= std::uint32_t((p[i] & 0xff00) != (c[i] & 0xff00)) << (2 * i + 1);
  }
  const bool colour = c[0] != c[1] || c[0] != c[2];
  sym |= std::uint32_t(colour) << 6;
  enc.encode_symbol(m.used, sym);
  std::int32_t dl = (c[0] & 255) - (p[0] & 255), dh = (c[0] >> 8) - (p[0] >> 8);
  if (sym & 1) enc.encode_symbol(m.diff[0], fold_u8(dl));
  if (sym & 2) enc.encode_symbol(m.diff[1], fold_u8(dh));
  if (!colour) return;
  if (sym & 4) enc.encode_symbol(m.diff[2], fold_u8((c[1] & 255) - clamp_u8(dl + (p[1] & 255))));
  if (sym & 16) {
    dl = (dl + (c[1] & 255) - (p[1] & 255)) / 2;
    enc.encode_symbol(m.diff[4], fold_u8((c[2] & 255) - clamp_u8(dl + (p[2] & 255))));
  }
  if (sym & 8) enc.encode_symbol(m.diff[3], fold_u8((c[1] >> 8) - clamp_u8(dh + (p[1] >> 8))));
  if (sym & 32) {
    dh = (dh + (c[1] >> 8) - (p[1] >> 8)) / 2;
    enc.encode_symbol(m.diff[5], fold_u8((c[2] >> 8) - clamp_u8(dh + (p[2] >> 8))));
  }
}

}  // namespace ramus::laz
