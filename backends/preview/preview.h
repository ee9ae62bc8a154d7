// `ramus preview`: a picture of a tree from the front (looking along +y: x right, z up) and from
// the side (looking along -x: y right, z up), side by side at the same scale, as PNG (rasterized,
// see raster.h) or SVG (projected polygons sorted back to front; leaves as leaf outlines).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mesh/tree_mesh.h"

namespace ramus::preview {

struct PreviewOptions {
  int width = 1200;  // the whole picture; each view gets half the width
  int height = 800;
  int supersample = 3;  // PNG anti-aliasing: samples per pixel along each axis
  // Grown trees are closed tubes and two-faced cards, so their back faces are hidden anyway and
  // culling them halves the work. Meshes read from files may be open or wound either way: they
  // are drawn from both sides, each triangle lit on the side facing the viewer.
  bool cull_back_faces = true;
};

// Throws std::invalid_argument for sizes outside 16..8192 or a supersampling factor outside 1..4.
void check_preview_options(const PreviewOptions& options);

// The faint rule between the two views of an RGB picture of options' size.
void draw_view_divider(std::vector<std::uint8_t>& rgb, const PreviewOptions& options);

// The picture as 8-bit RGB, rows top to bottom. Throws std::invalid_argument for sizes outside
// 16..8192 or a supersampling factor outside 1..4.
std::vector<std::uint8_t> render_rgb(const mesh::TreeMesh& tree, const PreviewOptions& options);

std::string render_png(const mesh::TreeMesh& tree, const PreviewOptions& options);
std::string render_svg(const mesh::TreeMesh& tree, const PreviewOptions& options);

// Writes .png or .svg (by the extension of `path`) atomically.
void write_preview(const mesh::TreeMesh& tree, const std::string& path,
                   const PreviewOptions& options);

}  // namespace ramus::preview
