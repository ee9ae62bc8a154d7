// The manifest of a tiled plot (`ramus tile`): DIR/manifest.json, JSON "ramus-tiles" version 1,
// documented in docs/scale.md. Each tile has a core (a cell of a square grid aligned to world
// coordinate 0, so tiles of one plot line up whatever the files) and a buffered box (the core
// grown by the buffer on every side); its file holds the points of the buffered box. A tree
// belongs to the tile whose core holds its base, so the cores partition the trees and the
// buffers give each kept tree its whole crown.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/atomic_file.h"        // WriteError
#include "formats/point_cloud_io.h"  // FormatError

namespace ramus {

// A box in the ground plane: [x0, x1) x [y0, y1).
struct TileBox {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool contains(double x, double y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
};

struct TileEntry {
  int id = 0;  // what `ramus reconstruct MANIFEST --tile K` names
  TileBox core, buffered;
  std::string file;  // point file of the buffered box, relative to the manifest's folder
  std::uint64_t points = 0;
};

struct TileManifest {
  double size = 0, buffer = 0;
  double thin = 0;                   // voxel edge the points were thinned on (0: not thinned)
  std::vector<std::string> sources;  // the scans tiled, as given
  std::vector<TileEntry> tiles;      // in id order, ids 0..n-1
};

std::string tile_manifest_to_json(const TileManifest& manifest);
// Strict like the skeleton reader: FormatError with line, column and JSON location for unknown
// keys, wrong types, ids out of order or a core outside its buffered box.
TileManifest tile_manifest_from_json(std::string_view text, const std::string& name);

void write_tile_manifest(const std::string& path, const TileManifest& manifest);
TileManifest read_tile_manifest(const std::string& path);

}  // namespace ramus
