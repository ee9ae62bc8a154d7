#include "backends/texture/image.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <cstring>
#include <memory>

#include "backends/preview/png.h"
#include "core/input_file.h"

namespace ramus::texture {

Image Image::crop(int x, int y, int w, int h) const {
  Image out(w, h);
  for (int r = 0; r < h; ++r) std::memcpy(out.at(0, r), at(x, y + r), std::size_t(w) * 3);
  return out;
}

void Image::paste(const Image& src, int x, int y) {
  for (int r = 0; r < src.height; ++r) {
    std::memcpy(at(x, y + r), src.at(0, r), std::size_t(src.width) * 3);
  }
}

Image decode_image(const std::string& bytes, const std::string& name) {
  int w = 0, h = 0, n = 0;
  std::unique_ptr<stbi_uc, void (*)(void*)> data(
      stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size()), &w,
                            &h, &n, 3),
      stbi_image_free);
  if (!data) {
    throw ImageError(name + ": not a readable picture (" + stbi_failure_reason() + ")");
  }
  Image out(w, h);
  std::memcpy(out.rgb.data(), data.get(), out.rgb.size());
  return out;
}

Image read_image(const std::string& path) {
  std::string bytes, error;
  if (!read_input_file(path, bytes, error)) throw ImageError(path + ": " + error);
  return decode_image(bytes, path);
}

std::string encode_png(const Image& image) {
  return preview::encode_png(image.rgb.data(), image.width, image.height, 3);
}

}  // namespace ramus::texture

namespace ramus::texture {

std::string encode_jpeg(const Image& image, int quality) {
  std::string out;
  auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), std::size_t(size));
  };
  if (image.width <= 0 || image.height <= 0 ||
      !stbi_write_jpg_to_func(append, &out, image.width, image.height, 3, image.rgb.data(),
                              quality)) {
    throw std::runtime_error("JPEG encoding failed");
  }
  return out;
}

}  // namespace ramus::texture
