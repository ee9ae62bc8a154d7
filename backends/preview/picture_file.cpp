#include "backends/preview/picture_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "backends/preview/view.h"
#include "core/atomic_file.h"

namespace ramus::preview {

std::string svg_colour(const Rgb& c) {
  char buf[8];
  auto b = [](float v) { return int(std::lround(std::clamp(v, 0.0f, 1.0f) * 255)); };
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", b(c.r), b(c.g), b(c.b));
  return buf;
}

std::string svg_open(int width, int height) {
  std::string svg;
  char buf[160];
  std::snprintf(buf, sizeof buf,
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"0 "
                "0 %d %d\">\n",
                width, height, width, height);
  svg += buf;
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"" + svg_colour(kBackground) + "\"/>\n";
  std::snprintf(buf, sizeof buf,
                "<line x1=\"%d\" y1=\"0\" x2=\"%d\" y2=\"%d\" stroke=\"#cdcdcd\"/>\n", width / 2,
                width / 2, height);
  svg += buf;
  return svg;
}

void write_picture(const std::string& path, const std::function<std::string()>& png,
                   const std::function<std::string()>& svg) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".png") {
    write_file_atomically(path, png());
  } else if (ext == ".svg") {
    write_file_atomically(path, svg());
  } else {
    throw std::invalid_argument("a preview file name must end in .png or .svg: " + path);
  }
}

}  // namespace ramus::preview
