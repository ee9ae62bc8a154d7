// `ramus preview` of a laser scan: its points as dots, from the front and the side like a tree
// (preview.h), so a scan and the trees grown from it read the same way. Dots are shaded by depth
// (nearer is lighter), which is the only cue to the crown's depth a flat dot can give.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "backends/preview/preview.h"
#include "core/point_cloud.h"

namespace ramus::preview {

// 8-bit RGB, rows top to bottom; throws std::invalid_argument for an empty cloud and for sizes
// check_preview_options refuses.
std::vector<std::uint8_t> render_points_rgb(const PointCloud& cloud, const PreviewOptions& options);

std::string render_points_png(const PointCloud& cloud, const PreviewOptions& options);
// One square per output pixel a point falls on (the nearest point's), painted back to front:
// the file grows with the picture, not with the scan.
std::string render_points_svg(const PointCloud& cloud, const PreviewOptions& options);

// Writes .png or .svg (by the extension of `path`) atomically.
void write_points_preview(const PointCloud& cloud, const std::string& path,
                          const PreviewOptions& options);

}  // namespace ramus::preview
