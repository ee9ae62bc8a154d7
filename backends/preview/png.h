// PNG encoding in memory (stb_image_write, from Debian's libstb), so callers can hand the bytes
// to write_file_atomically or embed them in a glTF buffer.
#pragma once

#include <cstdint>
#include <string>

namespace ramus::preview {

// `pixels`: rows top to bottom, `channels` bytes per pixel (3 RGB or 4 RGBA). Throws
// std::runtime_error if encoding fails.
std::string encode_png(const std::uint8_t* pixels, int width, int height, int channels);

}  // namespace ramus::preview
