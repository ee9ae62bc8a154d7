#include "backends/preview/png.h"

#include <stb_image_write.h>

#include <stdexcept>

namespace ramus::preview {
namespace {

void append(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), std::size_t(size));
}

}  // namespace

std::string encode_png(const std::uint8_t* pixels, int width, int height, int channels) {
  std::string out;
  if (width <= 0 || height <= 0 ||
      !stbi_write_png_to_func(append, &out, width, height, channels, pixels, width * channels)) {
    throw std::runtime_error("PNG encoding failed");
  }
  return out;
}

}  // namespace ramus::preview
