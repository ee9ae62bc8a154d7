// ramus tile SCAN... -o DIR --size S --buffer B [--thin V]
// Streams the points of the scans into square tiles of a grid aligned to world coordinate 0:
// each tile's file (DIR/K.las) holds the points of its core grown by the buffer on every side,
// and DIR/manifest.json lists the tiles (formats/tile_manifest.h; docs/scale.md). Points go to
// per-tile spill files in blocks as they are read, so memory holds one scan (with --thin, its
// thinned points) and one block per tile, not every tile.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>

#include "cli/command.h"
#include "cli/output_path.h"
#include "formats/las_file.h"
#include "formats/point_cloud_io.h"
#include "formats/tile_manifest.h"
#include "formats/voxel_thin.h"

namespace ramus::cli {
namespace {

struct TileArgs {
  std::vector<std::string> scans;
  std::string dir;
  double size = 20, buffer = 6, thin = 0;
};

using CellKey = std::pair<std::int64_t, std::int64_t>;  // (column, row) of the core grid

// One tile's points while the scans are read: a block in memory, spilled to DIR/.K.part.
struct TileSpill {
  std::vector<Vec3> block;
  std::uint64_t points = 0, core_points = 0;
  std::filesystem::path part;

  void flush() {
    if (block.empty()) return;
    std::ofstream out(part, std::ios::binary | std::ios::app);
    out.write(reinterpret_cast<const char*>(block.data()),
              std::streamsize(block.size() * sizeof(Vec3)));
    if (!out) throw UserError("cannot write " + part.string());
    block.clear();
  }
};

constexpr std::size_t kBlock = 1 << 15;  // points per tile held before spilling

int run_tile(const TileArgs& a, const GlobalOptions& global) {
  if (!(a.buffer < 1e6 && a.size < 1e6)) throw UserError("--size and --buffer must be under 1e6");
  const std::filesystem::path dir(a.dir);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) {
    throw UserError("cannot create the output folder " + a.dir);
  }
  std::map<CellKey, TileSpill> tiles;
  std::unique_ptr<VoxelThinner> thinner;
  if (a.thin > 0) thinner = std::make_unique<VoxelThinner>(a.thin);
  std::uint64_t read = 0, kept = 0;
  auto cell = [&](double v) { return std::int64_t(std::floor(v / a.size)); };
  for (const std::string& scan : a.scans) {
    PointCloud cloud;
    try {
      // Thinned while it is read, against the cubes of the scans before it.
      ReadOptions options;
      options.thin = a.thin;
      options.thinner = thinner.get();
      ReadReport report;
      cloud = read_point_cloud(scan, options, &report);
      read += report.points_before_thinning;
    } catch (const FormatError& e) {
      throw UserError(e.what());
    }
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      const Vec3 w = cloud.world(i);
      ++kept;
      const CellKey home{cell(w.x), cell(w.y)};
      // Every tile whose buffered box holds the point.
      for (std::int64_t cy = cell(w.y - a.buffer); cy <= cell(w.y + a.buffer); ++cy) {
        for (std::int64_t cx = cell(w.x - a.buffer); cx <= cell(w.x + a.buffer); ++cx) {
          const double x0 = double(cx) * a.size - a.buffer, x1 = double(cx + 1) * a.size + a.buffer;
          const double y0 = double(cy) * a.size - a.buffer, y1 = double(cy + 1) * a.size + a.buffer;
          if (w.x < x0 || w.x >= x1 || w.y < y0 || w.y >= y1) continue;
          TileSpill& t = tiles[{cx, cy}];
          if (t.part.empty()) {
            t.part = dir / (".tile_" + std::to_string(cx) + "_" + std::to_string(cy) + ".part");
            std::filesystem::remove(t.part, ec);
          }
          t.block.push_back(w);
          ++t.points;
          if (CellKey{cx, cy} == home) ++t.core_points;
          if (t.block.size() >= kBlock) t.flush();
        }
      }
    }
  }
  // Tiles whose core holds points, in row order (y, then x): ids 0..n-1.
  std::vector<std::pair<CellKey, TileSpill*>> order;
  for (auto& [key, t] : tiles) {
    if (t.core_points > 0) order.push_back({key, &t});
  }
  std::sort(order.begin(), order.end(), [](const auto& p, const auto& q) {
    return std::tie(p.first.second, p.first.first) < std::tie(q.first.second, q.first.first);
  });
  TileManifest m;
  m.size = a.size;
  m.buffer = a.buffer;
  m.thin = a.thin;
  m.sources = a.scans;
  for (const auto& [key, t] : order) {
    TileEntry e;
    e.id = int(m.tiles.size());
    e.core = {double(key.first) * a.size, double(key.second) * a.size,
              double(key.first + 1) * a.size, double(key.second + 1) * a.size};
    e.buffered = {e.core.x0 - a.buffer, e.core.y0 - a.buffer, e.core.x1 + a.buffer,
                  e.core.y1 + a.buffer};
    e.file = std::to_string(e.id) + ".las";
    e.points = t->points;
    // The tile's points back from its spill file, about the tile's centre.
    t->flush();
    PointCloud cloud;
    cloud.offset = {std::round((e.core.x0 + e.core.x1) / 2),
                    std::round((e.core.y0 + e.core.y1) / 2), 0};
    cloud.source = e.file;
    cloud.positions.reserve(t->points);
    {
      std::ifstream in(t->part, std::ios::binary);
      Vec3 w;
      while (in.read(reinterpret_cast<char*>(&w), sizeof w)) {
        cloud.positions.push_back(Vec3f(w - cloud.offset));
      }
    }
    write_point_cloud_las((dir / e.file).string(), cloud);
    m.tiles.push_back(e);
  }
  for (auto& [key, t] : tiles) std::filesystem::remove(t.part, ec);
  if (m.tiles.empty()) throw UserError("the scans hold no points: there is nothing to tile");
  write_tile_manifest((dir / "manifest.json").string(), m);
  if (!global.quiet) {
    std::fprintf(stderr,
                 "ramus: wrote %s/manifest.json (%zu tiles of %g + %g buffer) from %llu points"
                 "%s\n",
                 a.dir.c_str(), m.tiles.size(), a.size, a.buffer,
                 static_cast<unsigned long long>(read),
                 thinner ? (", " + std::to_string(kept) + " kept by --thin").c_str() : "");
  }
  return 0;
}

}  // namespace

void add_tile(CLI::App& app, const GlobalOptions& global, std::function<int()>& run) {
  auto args = std::make_shared<TileArgs>();
  CLI::App* sub = app.add_subcommand(
      "tile", "split scans into square tiles with buffers for parallel reconstruction");
  sub->add_option("scans", args->scans, "point clouds: .ply, .xyz/.txt/.asc/.csv, .las, .pcd")
      ->required();
  output_path(sub->add_option("-o,--output", args->dir,
                              "output folder: its tiles (K.las) and manifest.json"))
      ->required();
  sub->add_option("--size", args->size, "edge of a tile's core in metres (default 20)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--buffer", args->buffer,
                  "margin around each core in metres (default 6); must cover half the widest "
                  "crown, or trees at a border are cut")
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--thin", args->thin,
                  "keep the first point of each voxel of this edge (metres) while the scan is read")
      ->check(CLI::PositiveNumber);
  sub->callback(
      [args, &global, &run] { run = [args, &global] { return run_tile(*args, global); }; });
}

}  // namespace ramus::cli
