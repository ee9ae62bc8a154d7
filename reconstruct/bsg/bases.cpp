#include "reconstruct/bsg/bases.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "reconstruct/bsg/ground_surface.h"
#include "reconstruct/bsg/kdtree.h"

namespace ramus::bsg {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kSlope = 0.35;         // steepest terrain taken as ground: about 20 degrees
constexpr double kMinTrunkShare = 0.1;  // a further trunk has this share of the strongest's bark
constexpr double kMinCellShare = 0.1;   // a trunk's cell holds this share of the densest cell
// A layer of a trunk below its footprint's slab holds this share of the slab's points per layer
// (trunk_foot); layers hold at least kFootLayerPoints of the slab's points; the foot is at most
// kMaxFootLayers layers below the slab.
constexpr double kMinFootShare = 0.25;
constexpr double kFootLayerPoints = 8;
constexpr double kMaxFootLayers = 4096;

// A 2D grid over the xy bounds of the kept points.
struct Grid2 {
  double x0 = 0, y0 = 0, cell = 1;
  int nx = 1, ny = 1;
  int ix(double x) const { return std::clamp(int((x - x0) / cell), 0, nx - 1); }
  int iy(double y) const { return std::clamp(int((y - y0) / cell), 0, ny - 1); }
  int at(const Eigen::Vector3d& p) const { return iy(p.y()) * nx + ix(p.x()); }
};

Grid2 make_grid(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double cell,
                double max_cells) {
  Grid2 g;
  g.x0 = lo.x();
  g.y0 = lo.y();
  // Very wide scans get coarser cells rather than unbounded memory.
  const double area = std::max(hi.x() - lo.x(), cell) * std::max(hi.y() - lo.y(), cell);
  g.cell = std::max(cell, std::sqrt(area / max_cells));
  g.nx = int((hi.x() - lo.x()) / g.cell) + 1;
  g.ny = int((hi.y() - lo.y()) / g.cell) + 1;
  return g;
}

// The lowest point of each cell of `g` (infinity where the cell is empty).
std::vector<double> lowest_points(const std::vector<Eigen::Vector3d>& pts,
                                  const std::vector<std::uint8_t>& keep, const Grid2& g) {
  std::vector<double> low(std::size_t(g.nx) * g.ny, kInf);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (keep[i]) low[g.at(pts[i])] = std::min(low[g.at(pts[i])], pts[i].z());
  }
  return low;
}

// The ground as a lower envelope: the lowest point of each coarse cell, spread to every other
// cell with a bounded slope. Where there is no terrain (most tree scans) this is the trunk base
// seen from around the tree, so crown points far above it are never mistaken for ground.
std::vector<double> ground_envelope(const std::vector<double>& low, const Grid2& g) {
  std::vector<std::pair<int, double>> occupied;
  for (int c = 0; c < int(low.size()); ++c) {
    if (low[c] < kInf) occupied.emplace_back(c, low[c]);
  }
  std::vector<double> ground(low.size(), kInf);
  for (int c = 0; c < int(low.size()); ++c) {
    for (auto [o, z] : occupied) {
      const double dx = (c % g.nx - o % g.nx) * g.cell, dy = (c / g.nx - o / g.nx) * g.cell;
      ground[c] = std::min(ground[c], z + kSlope * std::sqrt(dx * dx + dy * dy));
    }
  }
  return ground;
}

// The lowest point of a grid cell, with the cell's centre.
struct LowPoint {
  Eigen::Vector2d xy;
  double z;
};

std::vector<LowPoint> low_points(const std::vector<double>& lowest, const Grid2& g) {
  std::vector<LowPoint> out;
  for (int c = 0; c < int(lowest.size()); ++c) {
    if (lowest[c] < kInf) {
      out.push_back(
          {{g.x0 + (c % g.nx + 0.5) * g.cell, g.y0 + (c / g.nx + 0.5) * g.cell}, lowest[c]});
    }
  }
  return out;
}

// The ground at `xy` as the rest of the scan predicts it: the envelope of the lowest points of
// the cells farther than `exclude` from `xy`. A trunk stands on the ground, so its base is not
// above this prediction; the tip of a hanging or drooping branch is its own cell's lowest point,
// and only this leave-one-out view shows that it floats above the ground seen elsewhere.
double predicted_ground(const std::vector<LowPoint>& lows, const Eigen::Vector2d& xy,
                        double exclude) {
  double best = kInf;
  for (const LowPoint& l : lows) {
    const double d = (l.xy - xy).norm();
    if (d > exclude) best = std::min(best, l.z + kSlope * d);
  }
  return best;
}

struct Cluster {
  double sx = 0, sy = 0, zmin = kInf, n = 0;  // n: points
  double area = 0;                            // the bark they sample: points x squared spacing
  double x0 = kInf, x1 = -kInf, y0 = kInf, y1 = -kInf;
};

struct Footprint : Cluster {
  std::vector<int> cells;
};

// The cells of a footprint and their neighbours, sorted: where its trunk's bark lies.
std::vector<int> cells_around(const Grid2& g, const std::vector<int>& cells) {
  std::vector<int> out;
  for (int c : cells) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int x = c % g.nx + dx, y = c / g.nx + dy;
        if (x >= 0 && y >= 0 && x < g.nx && y < g.ny) out.push_back(y * g.nx + x);
      }
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// The bark in the slab above the footprint (its cells and their neighbours): a trunk rises
// through it, a low branch or a fallen twig does not.
double bark_above(const Grid2& g, const Footprint& f, const std::vector<double>& above) {
  double sum = 0;
  for (int c : cells_around(g, f.cells)) sum += above[c];
  return sum;
}

// The extent of a footprint along and across its principal axes, its cells weighted by
// `weight[c]` (each 1 when null): sqrt(12) times the standard deviations, so that a uniform
// segment measures its length and width. Along the principal axes, not the grid's: a half ring
// of bark measures 2.45 r by 1.06 r however it lies, and a wall piece its length by about
// nothing. Weighted by points, a low branch that crosses the slab beside a trunk adds cells but
// few points (the conifer turned to 120 degrees: the trunk's half ring and a branch of the
// lowest whorl made a footprint 0.78 m by 0.2 m along the grid, taken for a piece of wall, and
// the tree was rooted on the branch).
void principal_extent(const Grid2& g, const std::vector<int>& cells,
                      const std::vector<double>* weight, double& length, double& thickness) {
  auto at = [&](int c) {
    return Eigen::Vector2d((c % g.nx + 0.5) * g.cell, (c / g.nx + 0.5) * g.cell);
  };
  auto w = [&](int c) { return weight ? (*weight)[std::size_t(c)] : 1.0; };
  double sw = 0;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (int c : cells) sw += w(c), mean += w(c) * at(c);
  length = thickness = 0;
  if (!(sw > 0)) return;
  mean /= sw;
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (int c : cells) cov += w(c) * (at(c) - mean) * (at(c) - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov / sw);
  length = std::sqrt(12.0 * std::max(eig.eigenvalues()(1), 0.0));
  thickness = std::sqrt(12.0 * std::max(eig.eigenvalues()(0), 0.0));
}

// Connected groups of the cells with in[c] != 0 (cells up to two apart are neighbours, which
// bridges the holes of sparse sampling). A trunk is a compact footprint with a dense peak; a
// wall is a long one however dense it is.
std::vector<Footprint> footprints(const Grid2& g, const std::vector<double>& count,
                                  const std::vector<double>& area, const std::vector<double>& zmin,
                                  const std::vector<std::uint8_t>& in) {
  std::vector<int> label(count.size(), -1);
  std::vector<Footprint> out;
  std::vector<int> stack;
  for (int s = 0; s < int(count.size()); ++s) {
    if (label[s] >= 0 || !in[s]) continue;
    Footprint cl;
    label[s] = int(out.size());
    stack.assign(1, s);
    while (!stack.empty()) {
      const int c = stack.back();
      stack.pop_back();
      const int cx = c % g.nx, cy = c / g.nx;
      const double x = g.x0 + (cx + 0.5) * g.cell, y = g.y0 + (cy + 0.5) * g.cell;
      cl.sx += count[c] * x, cl.sy += count[c] * y, cl.n += count[c];
      cl.area += area[c];
      cl.zmin = std::min(cl.zmin, zmin[c]);
      cl.cells.push_back(c);
      cl.x0 = std::min(cl.x0, x), cl.x1 = std::max(cl.x1, x);
      cl.y0 = std::min(cl.y0, y), cl.y1 = std::max(cl.y1, y);
      for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
          const int nx = cx + dx, ny = cy + dy;
          if (nx < 0 || ny < 0 || nx >= g.nx || ny >= g.ny) continue;
          const int n = ny * g.nx + nx;
          if (label[n] < 0 && in[n]) label[n] = label[s], stack.push_back(n);
        }
      }
    }
    out.push_back(cl);
  }
  return out;
}

// Whether a footprint is a long thin line (a fence, the foot of a wall): its cells' principal
// extent exceeds `max_width` and the cross extent is under a tenth of it. Principal axes, not
// the bounding box, so that a fence at 45 degrees is a line too.
bool is_line(const Grid2& g, const Footprint& f, double max_width) {
  if (f.cells.size() < 3) return false;
  double length = 0, thickness = 0;
  principal_extent(g, f.cells, nullptr, length, thickness);
  return length > max_width && thickness < 0.1 * length;
}

// The squared spacing of the scan at each of pts[ids[i]]: the squared distance to its nearest
// other point (duplicates of merged scans skipped), at most max_spacing^2.
std::vector<double> squared_spacing(const std::vector<Eigen::Vector3d>& pts,
                                    const std::vector<std::uint32_t>& ids, double max_spacing) {
  std::vector<double> s2(ids.size(), max_spacing * max_spacing);
  const PointIndex index(pts, ids);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ids.size(), 4096), [&](const auto& range) {
    for (std::size_t i = range.begin(); i < range.end(); ++i) {
      const double d2 = nearest_other_d2(index, pts[ids[i]], true);
      if (d2 >= 0) s2[i] = std::min(s2[i], d2);
    }
  });
  return s2;
}

// The squared spacing of the scan around each cell of `g`: the median of the squared spacings
// `s2` of the points (`cell[i]`: point i's cell) in the block of 3 x 3 tiles of `tile` x `tile`
// cells around the cell's tile. The scan's resolution changes slowly across a plot, while one
// point's spacing is noisy (a random subsample spaces its points by chance), so it is pooled
// over a block of a few hundred points.
std::vector<double> spacing_field(const Grid2& g, const std::vector<int>& cell,
                                  const std::vector<double>& s2, int tile) {
  const int tx = (g.nx + tile - 1) / tile, ty = (g.ny + tile - 1) / tile;
  const auto tile_of = [&](int c) { return (c / g.nx / tile) * tx + (c % g.nx) / tile; };
  std::vector<std::pair<int, double>> by_tile(cell.size());
  for (std::size_t i = 0; i < cell.size(); ++i) by_tile[i] = {tile_of(cell[i]), s2[i]};
  std::sort(by_tile.begin(), by_tile.end());
  std::vector<std::size_t> first(std::size_t(tx) * ty + 1, by_tile.size());
  for (std::size_t i = by_tile.size(); i-- > 0;) first[std::size_t(by_tile[i].first)] = i;
  for (std::size_t t = first.size() - 1; t-- > 0;) first[t] = std::min(first[t], first[t + 1]);
  std::vector<double> median(std::size_t(tx) * ty, 0.0), pool;
  for (int t = 0; t < tx * ty; ++t) {
    if (first[t] == first[t + 1]) continue;  // no point in the tile: no cell asks
    pool.clear();
    for (int y = std::max(0, t / tx - 1); y <= std::min(ty - 1, t / tx + 1); ++y) {
      for (int x = std::max(0, t % tx - 1); x <= std::min(tx - 1, t % tx + 1); ++x) {
        const int n = y * tx + x;
        for (std::size_t i = first[n]; i < first[n + 1]; ++i) pool.push_back(by_tile[i].second);
      }
    }
    std::nth_element(pool.begin(), pool.begin() + std::ptrdiff_t(pool.size() / 2), pool.end());
    median[std::size_t(t)] = pool[pool.size() / 2];
  }
  std::vector<double> field(std::size_t(g.nx) * g.ny);
  for (int c = 0; c < int(field.size()); ++c) field[c] = median[std::size_t(tile_of(c))];
  return field;
}

// The height of a trunk's foot below `top`, the bottom of its footprint's slab, from the heights
// `z` of the points over the footprint (cells_around): the trunk goes on down through the layers
// that hold at least kMinFootShare of the points per layer of the slab above, and the foot is the
// lowest point of the last of them (the ground under a trunk, where there is some, is as dense
// and goes with it). Whips that hang beside the trunk below its foot (a weeping tree on a bank, a
// drooping limb over a slope) hold a few per cent of a trunk's points per layer and stop the
// descent: the lowest point under the footprint was one of them on the weeping example turned to
// three of six azimuths, and the tree hung from the whip's tip. Layers are `cell` high, or as
// many cells as the slab needs for kFootLayerPoints points a layer: an empty layer of a sparse
// scan (airborne, a few points on the trunk) is chance, not the foot.
double trunk_foot(const std::vector<double>& z, double top, double cell, double slab) {
  double in_slab = 0;
  for (double h : z) in_slab += h >= top && h < top + slab;
  const double per_cell = in_slab * cell / slab;
  const double layer = cell * std::max(1.0, std::ceil(kFootLayerPoints / std::max(per_cell, 1e-9)));
  if (!(layer < slab * kMaxFootLayers)) return top;
  std::vector<double> count, lowest;  // per layer below `top`
  for (double h : z) {
    if (h >= top) continue;
    // An outlier far below adds no layer: the descent stops at the first thin one anyway.
    const double k = std::floor((top - h) / layer);
    if (!(k < kMaxFootLayers)) continue;
    const std::size_t i = std::size_t(k);
    if (i >= count.size()) count.resize(i + 1, 0.0), lowest.resize(i + 1, kInf);
    count[i] += 1;
    lowest[i] = std::min(lowest[i], h);
  }
  const double needed = std::max(1.0, kMinFootShare * in_slab * layer / slab);
  double foot = top;
  for (std::size_t i = 0; i < count.size() && count[i] >= needed; ++i) foot = lowest[i];
  return foot;
}

}  // namespace

Bases find_bases(const std::vector<Eigen::Vector3d>& pts, const std::vector<std::uint8_t>& keep,
                 const BaseParams& p) {
  Bases out;
  out.terrain.assign(pts.size(), 0);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(kInf), hi = -lo;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (keep[i]) lo = lo.cwiseMin(pts[i]), hi = hi.cwiseMax(pts[i]);
  }
  if (!(lo.x() <= hi.x())) {
    out.note = "no points";
    return out;
  }
  const Grid2 coarse = make_grid(lo, hi, std::max(4 * p.cell, (hi.z() - lo.z()) / 10), 2500);
  const std::vector<double> low = lowest_points(pts, keep, coarse);
  const std::vector<double> ground = ground_envelope(low, coarse);
  const Grid2 fine = make_grid(lo, hi, p.cell, 4e6);
  // Ground may rise by the envelope's slope across one coarse cell.
  const double band = std::max(p.ground_band, kSlope * coarse.cell);
  std::vector<double> count(std::size_t(fine.nx) * fine.ny, 0.0), zmin(count.size(), kInf);
  std::vector<double> above(count.size(), 0.0);    // the next slab up: trunks continue there
  std::vector<double> lowest(count.size(), kInf);  // lowest point of each fine cell, terrain too
  std::vector<std::uint32_t> slabs;                // the points of the slab and the one above
  std::vector<int> slab_cell;                      // and their cells
  std::size_t standing = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (!keep[i]) continue;
    lowest[fine.at(pts[i])] = std::min(lowest[fine.at(pts[i])], pts[i].z());
    const double h = pts[i].z() - ground[coarse.at(pts[i])];
    if (h < band) {
      out.terrain[i] = p.remove_terrain ? 1 : 0;
      continue;
    }
    ++standing;
    if (h < band + p.slab) {
      const int c = fine.at(pts[i]);
      count[c] += 1;
      zmin[c] = std::min(zmin[c], pts[i].z());
      slabs.push_back(std::uint32_t(i));
      slab_cell.push_back(c);
    } else if (h < band + 2 * p.slab) {
      above[fine.at(pts[i])] += 1;
      slabs.push_back(std::uint32_t(i));
      slab_cell.push_back(fine.at(pts[i]));
    }
  }
  if (standing == 0) {
    out.note = "every point lies in the terrain layer: no tree stands above the ground";
    return out;
  }
  // The layer is ground only where it is a wide flat surface (ground_surface.h): elsewhere it is
  // the lowest branches of a scan without ground, and stays.
  if (p.remove_terrain) {
    std::vector<std::uint32_t> layer;
    std::vector<Eigen::Vector3d> layer_pos;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      if (out.terrain[i]) layer.push_back(std::uint32_t(i)), layer_pos.push_back(pts[i]);
    }
    GroundSurfaceParams gp;
    gp.min_extent = 2 * coarse.cell;
    const std::vector<std::uint8_t> ground = ground_surface(layer_pos, gp);
    for (std::size_t j = 0; j < layer.size(); ++j) out.terrain[layer[j]] = ground[j];
  }
  // The bark of each cell: each point stands for the square of the scan's spacing around it. A
  // scanner's samples thin out with the square of the range (one station in a plot sees the
  // trunk beside it tens of times denser than one 10 m away); the bark does not.
  const std::vector<double> s2 = squared_spacing(pts, slabs, fine.cell);
  const std::vector<double> field = spacing_field(fine, slab_cell, s2, 4);
  std::vector<double> area(count.size()), area_above(count.size());
  for (std::size_t c = 0; c < count.size(); ++c) {
    area[c] = count[c] * field[c];
    area_above[c] = above[c] * field[c];
  }
  const double peak = *std::max_element(area.begin(), area.end());
  // A trunk is vertical, so its cells hold far more points than those of low branches: at least
  // a tenth of the densest cell's. Counts alone leave the far trunks of a plot below any share of
  // the one beside the station; where the scan is sparser a tenth of the densest cell's bark will
  // do, but only away from the clusters of the counts (two cells or more), which stay as they
  // were: within a tree the far side and the skirt of branches are sparser too, and would widen
  // its trunk's footprint and pull its centre off the trunk. Clusters compare by bark after this.
  const double peak_count = *std::max_element(count.begin(), count.end());
  std::vector<std::uint8_t> dense(count.size()), any(count.size());
  for (std::size_t c = 0; c < count.size(); ++c) {
    dense[c] = count[c] >= std::max(2.0, kMinCellShare * peak_count);
    any[c] = count[c] >= 1;
  }
  std::vector<std::uint8_t> far_bark(count.size(), 0);
  for (int c = 0; c < int(count.size()); ++c) {
    if (count[c] < 2 || area[c] < kMinCellShare * peak || dense[c]) continue;
    bool near_dense = false;
    const int cx = c % fine.nx, cy = c / fine.nx;
    for (int y = std::max(0, cy - 2); y <= std::min(fine.ny - 1, cy + 2) && !near_dense; ++y) {
      for (int x = std::max(0, cx - 2); x <= std::min(fine.nx - 1, cx + 2); ++x) {
        near_dense |= dense[std::size_t(y * fine.nx + x)] != 0;
      }
    }
    far_bark[c] = !near_dense;
  }
  std::vector<Footprint> found = footprints(fine, count, area, zmin, dense);
  for (Footprint& f : footprints(fine, count, area, zmin, far_bark)) found.push_back(std::move(f));
  // Strongest first; a weaker cluster close to a stronger one is a low branch of its tree.
  std::stable_sort(found.begin(), found.end(),
                   [](const auto& a, const auto& b) { return a.area > b.area; });
  std::size_t too_wide = 0;
  const std::vector<LowPoint> lows = low_points(lowest, fine);
  // The same footprints down to single points: a sparse fence breaks into small dense pieces
  // that each look like a trunk, but together they are one long line.
  const std::vector<Footprint> loose = footprints(fine, count, area, zmin, any);
  std::vector<int> loose_of(count.size(), -1);
  for (std::size_t k = 0; k < loose.size(); ++k) {
    for (int c : loose[k].cells) loose_of[std::size_t(c)] = int(k);
  }
  std::vector<std::int8_t> loose_line(loose.size(), -1);  // -1: not measured yet
  double strongest = 0;
  std::vector<std::vector<int>> root_cells;  // per root: its footprint's cells
  for (const Footprint& cl : found) {
    const double width = std::max(cl.x1 - cl.x0, cl.y1 - cl.y0) + fine.cell;
    if (cl.n < 5) continue;
    if (out.roots.empty()) strongest = cl.area;
    // The strongest cluster is always a candidate; others must rise like a trunk.
    if (!out.roots.empty() && bark_above(fine, cl, area_above) < 0.5 * cl.area) continue;
    // A trunk's footprint is round (a half ring from one side); a piece of wall is a line.
    double length = 0, thickness = 0;
    principal_extent(fine, cl.cells, &count, length, thickness);
    if (width > p.max_trunk_width ||
        (width > 4 * fine.cell && thickness + fine.cell < 0.3 * (length + fine.cell))) {
      ++too_wide;
      continue;
    }
    const int lk = loose_of[std::size_t(cl.cells.front())];
    if (lk >= 0 && loose_line[lk] < 0) loose_line[lk] = is_line(fine, loose[lk], p.max_trunk_width);
    if (lk >= 0 && loose_line[lk] == 1) {
      ++too_wide;
      continue;
    }
    const Eigen::Vector3d base(cl.sx / cl.n, cl.sy / cl.n, cl.zmin);
    bool near_stronger = false;
    for (const auto& r : out.roots) {
      near_stronger |= (r - base).head<2>().norm() < p.min_separation;
    }
    if (near_stronger) continue;
    // Others must also stand on the ground that the rest of the scan shows (4.1: trunks rise
    // from the terrain; hanging and drooping branches end in the air).
    double foot = kInf;
    for (int c : cl.cells) foot = std::min(foot, lowest[c]);
    const double reach = 0.5 * width + fine.cell;
    const double predicted = predicted_ground(lows, base.head<2>(), reach + fine.cell);
    if (!out.roots.empty() && foot > predicted + p.ground_band) continue;
    // ... and be a trunk of comparable weight: the slab under a crown also collects bundles of
    // hanging twigs, which are vertical and reach the ground too but hold a few per cent of the
    // bark of a trunk (measured 3-4% of the points on the weeping and conifer examples).
    if (!out.roots.empty() && cl.area < kMinTrunkShare * strongest) continue;
    out.roots.push_back(base);
    out.reach.push_back(reach);
    root_cells.push_back(cl.cells);
  }
  if (out.roots.empty() && too_wide == 0) {
    // Sparse scans (airborne LiDAR) may hold only a handful of trunk points: fall back to the
    // strongest group of any standing points near the ground, when it is narrow enough.
    found = footprints(fine, count, area, zmin, any);
    std::stable_sort(found.begin(), found.end(),
                     [](const auto& a, const auto& b) { return a.n > b.n; });
    if (!found.empty()) {
      const Footprint& cl = found.front();
      const double width = std::max(cl.x1 - cl.x0, cl.y1 - cl.y0) + fine.cell;
      if (width <= p.max_trunk_width) {
        out.roots.emplace_back(cl.sx / cl.n, cl.sy / cl.n, cl.zmin);
        out.reach.push_back(0.5 * width + fine.cell);
        root_cells.push_back(cl.cells);
      } else {
        ++too_wide;
      }
    }
  }
  // Terrain removal must not eat the trunk: the ground band is low-density terrain only away
  // from the trunks (4.1), so the points under each base's footprint are kept, and the root
  // moves down to the trunk's foot (trunk_foot).
  std::vector<double> over_footprint;
  for (std::size_t r = 0; r < out.roots.size(); ++r) {
    const double reach2 = out.reach[r] * out.reach[r];
    const std::vector<int> around = cells_around(fine, root_cells[r]);
    over_footprint.clear();
    for (std::size_t i = 0; i < pts.size(); ++i) {
      if (!keep[i]) continue;
      if ((pts[i] - out.roots[r]).head<2>().squaredNorm() <= reach2) out.terrain[i] = 0;
      if (std::binary_search(around.begin(), around.end(), fine.at(pts[i])))
        over_footprint.push_back(pts[i].z());
    }
    out.roots[r].z() = trunk_foot(over_footprint, out.roots[r].z(), fine.cell, p.slab);
  }
  if (out.roots.empty()) {
    out.note = too_wide ? "the dense clusters near the ground are too wide to be trunks "
                          "(walls or hedges?): no tree base found"
                        : "no dense cluster of points near the ground: no tree base found";
  }
  return out;
}

}  // namespace ramus::bsg
