// What every preview picture file shares, whether it draws a tree's mesh (preview.h) or a scan's
// points (point_preview.h): the choice of PNG or SVG by the file name, written atomically, and
// the head of the SVG document (its size, the background and the line between the two views).
#pragma once

#include <functional>
#include <string>

#include "backends/preview/raster.h"

namespace ramus::preview {

// A colour as SVG writes it, #rrggbb.
std::string svg_colour(const Rgb& c);

// The opening of a preview's SVG document of w x h pixels, up to and with the line between the
// front and the side view; the caller adds the shapes and "</svg>\n".
std::string svg_open(int width, int height);

// Writes `path` (.png or .svg) atomically with the text the matching function renders; throws
// std::invalid_argument for another extension, WriteError when it cannot be written.
void write_picture(const std::string& path, const std::function<std::string()>& png,
                   const std::function<std::string()>& svg);

}  // namespace ramus::preview
