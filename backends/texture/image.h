// An RGB picture in memory, the unit the texture code works on (exemplars, tiles, atlases), and
// its PNG reading and writing. Pixels are 8-bit RGB, rows top to bottom; an alpha channel in a
// read file is dropped (tiles are opaque bark).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace ramus::texture {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // width * height * 3

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgb(std::size_t(w) * std::size_t(h) * 3, 0) {}

  std::uint8_t* at(int x, int y) { return &rgb[(std::size_t(y) * width + x) * 3]; }
  const std::uint8_t* at(int x, int y) const { return &rgb[(std::size_t(y) * width + x) * 3]; }

  // The w x h block whose top-left pixel is (x, y); it must lie inside.
  Image crop(int x, int y, int w, int h) const;
  // Copies `src` with its top-left pixel at (x, y); it must fit.
  void paste(const Image& src, int x, int y);
};

// Thrown for a file that is not a readable picture; the message names the file and the cause.
struct ImageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Decodes PNG (or any format stb_image reads: JPEG, BMP, TGA) bytes; `name` is for messages.
Image decode_image(const std::string& bytes, const std::string& name);
// The file's bytes decoded; throws ImageError if it cannot be read or decoded.
Image read_image(const std::string& path);
// PNG bytes of the picture.
std::string encode_png(const Image& image);
// JPEG bytes (baseline, quality 1..100): a tenth of the PNG's size for noisy pictures like
// bark, whose textures then do not dwarf the geometry in a glTF file.
std::string encode_jpeg(const Image& image, int quality);

// Squared RGB distance between two pixels.
inline int pixel_distance2(const std::uint8_t* a, const std::uint8_t* b) {
  int d0 = int(a[0]) - b[0], d1 = int(a[1]) - b[1], d2 = int(a[2]) - b[2];
  return d0 * d0 + d1 * d1 + d2 * d2;
}

}  // namespace ramus::texture
