#include "reconstruct/forest/stem_bases.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace ramus::forest {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

using Cell = std::pair<std::int64_t, std::int64_t>;

struct CellHash {
  std::size_t operator()(const Cell& c) const {
    return std::hash<std::int64_t>()(c.first * 73856093 ^ c.second * 19349663);
  }
};
template <class T>
using CellMap = std::unordered_map<Cell, T, CellHash>;

Cell cell_of(double x, double y, double size) {
  return {std::int64_t(std::floor(x / size)), std::int64_t(std::floor(y / size))};
}

struct Footprint {
  std::int64_t x0 = std::numeric_limits<std::int64_t>::max(), y0 = x0;
  std::int64_t x1 = std::numeric_limits<std::int64_t>::min(), y1 = x1;
  std::size_t points = 0, below = 0, above = 0;
  std::vector<Cell> cells;
};

}  // namespace

StemBases find_stem_bases(const PointCloud& cloud, const StemOptions& o) {
  StemBases out;
  const std::size_t n = cloud.size();
  out.ground.assign(n, 0);
  // Ground model: lowest point per cell, then the lowest of the 3 x 3 cells around, which reaches
  // past cells where the lowest return is a trunk or a low branch rather than the ground.
  CellMap<double> lowest;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 w = cloud.world(i);
    auto [it, fresh] = lowest.try_emplace(cell_of(w.x, w.y, o.ground_cell), w.z);
    if (!fresh) it->second = std::min(it->second, w.z);
  }
  CellMap<double> ground;
  for (const auto& [c, z] : lowest) {
    double g = kInf;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        auto it = lowest.find({c.first + dx, c.second + dy});
        if (it != lowest.end()) g = std::min(g, it->second);
      }
    }
    ground[c] = g;
  }
  auto ground_at = [&](double x, double y) {
    auto it = ground.find(cell_of(x, y, o.ground_cell));
    return it == ground.end() ? kInf : it->second;
  };
  // Slice points per footprint cell, and the points below and above the slice over each cell.
  struct Column {
    std::size_t slice = 0, below = 0, above = 0;
  };
  CellMap<Column> columns;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 w = cloud.world(i);
    const double h = w.z - ground_at(w.x, w.y);
    if (h < o.ground_band) {
      out.ground[i] = 1;
      continue;
    }
    const Cell c = cell_of(w.x, w.y, o.cell);
    if (h >= o.slice_low && h < o.slice_high) {
      ++columns[c].slice;
    } else if (h < o.slice_low) {
      ++columns[c].below;
    } else if (h < 2 * o.slice_high - o.slice_low) {
      ++columns[c].above;
    }
  }
  // Footprints: connected slice cells (two cells apart still connect, bridging the holes of
  // sparse sampling on far stems).
  // Starts in sorted order: the footprints then never depend on the hash table's order.
  std::vector<Cell> starts;
  for (const auto& [c, column] : columns) {
    if (column.slice > 0) starts.push_back(c);
  }
  std::sort(starts.begin(), starts.end());
  CellMap<int> label;
  std::vector<Footprint> found;
  for (const Cell& start : starts) {
    if (label.count(start)) continue;
    Footprint f;
    std::vector<Cell> stack{start};
    label[start] = int(found.size());
    while (!stack.empty()) {
      const Cell c = stack.back();
      stack.pop_back();
      const Column& col = columns.at(c);
      f.cells.push_back(c);
      f.points += col.slice;
      f.x0 = std::min(f.x0, c.first), f.x1 = std::max(f.x1, c.first);
      f.y0 = std::min(f.y0, c.second), f.y1 = std::max(f.y1, c.second);
      for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
          const Cell m{c.first + dx, c.second + dy};
          auto it = columns.find(m);
          if (it == columns.end() || it->second.slice == 0 || label.count(m)) continue;
          label[m] = int(found.size());
          stack.push_back(m);
        }
      }
    }
    // A stem continues below and above the slice over (or next to) its footprint.
    for (const Cell& c : f.cells) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          auto it = columns.find({c.first + dx, c.second + dy});
          if (it == columns.end()) continue;
          f.below += it->second.below;
          f.above += it->second.above;
        }
      }
    }
    found.push_back(std::move(f));
  }
  // Strongest first (ties by position, so the order is total).
  std::vector<std::size_t> order(found.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (found[a].points != found[b].points) return found[a].points > found[b].points;
    return std::tie(found[a].x0, found[a].y0) < std::tie(found[b].x0, found[b].y0);
  });
  for (std::size_t k : order) {
    const Footprint& f = found[k];
    const double width = double(std::max(f.x1 - f.x0, f.y1 - f.y0) + 1) * o.cell;
    const double thickness = double(std::min(f.x1 - f.x0, f.y1 - f.y0) + 1) * o.cell;
    if (f.points < std::size_t(o.min_points) || width > o.max_stem_width ||
        thickness < o.min_stem_width) {
      continue;
    }
    // A stem goes on above and below the slice (counted over the footprint's neighbourhood) with
    // a similar density: measured 0.8-1.2 times the slice's points on the example trees, under
    // 0.35 for hanging twigs that end near the ground.
    if (2 * f.above < f.points || 2 * f.below < f.points) continue;
    const double x = 0.5 * double(f.x0 + f.x1 + 1) * o.cell;
    const double y = 0.5 * double(f.y0 + f.y1 + 1) * o.cell;
    const bool near = std::any_of(out.bases.begin(), out.bases.end(), [&](const Vec3& b) {
      return std::hypot(b.x - x, b.y - y) < o.min_separation;
    });
    if (near) continue;
    out.bases.push_back({x, y, ground_at(x, y)});
  }
  return out;
}

PointCloud without_ground(const PointCloud& cloud, const std::vector<std::uint8_t>& ground) {
  PointCloud out;
  out.offset = cloud.offset;
  out.scanner = cloud.scanner;
  out.source = cloud.source;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (ground[i]) continue;
    out.positions.push_back(cloud.positions[i]);
    if (!cloud.normals.empty()) out.normals.push_back(cloud.normals[i]);
    if (!cloud.intensity.empty()) out.intensity.push_back(cloud.intensity[i]);
    if (!cloud.classification.empty()) out.classification.push_back(cloud.classification[i]);
  }
  return out;
}

}  // namespace ramus::forest
