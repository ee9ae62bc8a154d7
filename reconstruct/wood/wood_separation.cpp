// separate_wood(): the stages of the separation (wood_separation.h) in order.
#include "reconstruct/wood/wood_separation.h"

#include <tbb/parallel_for.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "reconstruct/bsg/kdtree.h"
#include "reconstruct/wood/features.h"
#include "reconstruct/wood/mixture.h"
#include "reconstruct/wood/otsu.h"
#include "reconstruct/wood/voxel_subsample.h"

namespace ramus {

namespace {

using wood::VoxelSubsample;

// Fewer finite points than this are too few for neighbourhood statistics: all wood.
constexpr std::size_t kMinPoints = 16;
// Samples of a neighbourhood at most; a scale's grid is r / 4, so a planar disc of radius r
// holds about 50 cells and 40 of them reach 0.9 r.
constexpr std::size_t kMaxNeighbours = 40;
// Cells the mixture is fitted to at most (every k-th cell beyond that).
constexpr std::size_t kMixtureSamples = 20000;

// Covariance features of every finite point at radius r, computed on the grid of edge r / 4.
std::vector<wood::Eigenfeatures> features_at(const std::vector<Eigen::Vector3d>& pts,
                                             const std::vector<std::uint8_t>& finite, double r) {
  const VoxelSubsample grid = wood::voxel_subsample(pts, finite, r / 4);
  const auto f = wood::multiscale_features(grid.centroids, {r}, kMaxNeighbours);
  std::vector<wood::Eigenfeatures> out(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (grid.cell[i] != VoxelSubsample::kNoCell) out[i] = f[0][grid.cell[i]];
  }
  return out;
}

// Every `stride`-th value, so that EM costs the same on any scan size.
std::vector<double> strided(const std::vector<double>& v, std::size_t max_count) {
  const std::size_t stride = std::max<std::size_t>(1, v.size() / max_count);
  std::vector<double> out;
  for (std::size_t i = 0; i < v.size(); i += stride) out.push_back(v[i]);
  return out;
}

// The neighbourhood graph of the fine grid's cells: each cell's 16 nearest, nearest first.
struct CellGraph {
  static constexpr std::size_t k = 16;
  std::vector<std::uint32_t> nb;  // cell c's neighbours at [c * k, c * k + count[c])
  std::vector<float> dist;
  std::vector<std::uint8_t> count;

  explicit CellGraph(const std::vector<Eigen::Vector3d>& cells, double radius)
      : nb(cells.size() * k), dist(cells.size() * k), count(cells.size()) {
    const bsg::PointIndex index(cells);
    tbb::parallel_for(std::size_t(0), cells.size(), [&](std::size_t c) {
      double d2[k];
      const std::size_t n = index.knn(cells[c], k, &nb[c * k], d2);
      std::size_t m = 0;
      for (; m < n && d2[m] <= radius * radius; ++m) dist[c * k + m] = float(std::sqrt(d2[m]));
      count[c] = std::uint8_t(m);
    });
  }
};

// Neighbour-mean steps of per-cell values over the graph. Jacobi steps: every cell reads the
// previous step only, so the order of the parallel loop never changes a result.
void smooth(const CellGraph& g, int steps, std::vector<double>& value) {
  std::vector<double> next(value.size());
  for (int s = 0; s < steps; ++s) {
    tbb::parallel_for(std::size_t(0), value.size(), [&](std::size_t c) {
      double sum = value[c];
      for (std::size_t j = 0; j < g.count[c]; ++j) sum += value[g.nb[c * g.k + j]];
      next[c] = sum / double(g.count[c] + 1);
    });
    value.swap(next);
  }
}

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

// Region growing over the wood cells: connected components through neighbours nearer than
// `link`. Wood forms long connected structures; a component whose bounding box diagonal stays
// under `min_extent` is a flat leaf card lying apart from the branches, unless it is the largest
// component (the stem, which is never dropped). Returns how many cells turned leaf.
std::size_t drop_small_wood_regions(const CellGraph& g, const std::vector<Eigen::Vector3d>& cells,
                                    double link, double min_extent,
                                    std::vector<std::uint8_t>& wood) {
  const std::size_t n = cells.size();
  std::vector<std::uint32_t> parent(n);
  for (std::size_t c = 0; c < n; ++c) parent[c] = std::uint32_t(c);
  for (std::size_t c = 0; c < n; ++c) {
    if (!wood[c]) continue;
    for (std::size_t j = 0; j < g.count[c] && g.dist[c * g.k + j] <= link; ++j) {
      const std::uint32_t d = g.nb[c * g.k + j];
      if (!wood[d]) continue;
      const std::uint32_t a = find_root(parent, std::uint32_t(c)), b = find_root(parent, d);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  }
  std::vector<Eigen::Vector3d> lo(n, Eigen::Vector3d::Constant(INFINITY)), hi(n, -lo[0]);
  std::vector<std::uint32_t> size(n, 0);
  for (std::size_t c = 0; c < n; ++c) {
    if (!wood[c]) continue;
    const std::uint32_t r = find_root(parent, std::uint32_t(c));
    lo[r] = lo[r].cwiseMin(cells[c]), hi[r] = hi[r].cwiseMax(cells[c]);
    ++size[r];
  }
  const auto largest = std::uint32_t(std::max_element(size.begin(), size.end()) - size.begin());
  std::size_t dropped = 0;
  for (std::size_t c = 0; c < n; ++c) {
    if (!wood[c]) continue;
    const std::uint32_t r = find_root(parent, std::uint32_t(c));
    if (r != largest && (hi[r] - lo[r]).norm() < min_extent) wood[c] = 0, ++dropped;
  }
  return dropped;
}

}  // namespace

WoodSeparation separate_wood(const PointCloud& cloud, const WoodOptions& o) {
  if (cloud.empty()) throw WoodError("the point cloud is empty");
  WoodSeparation res;
  const std::size_t n = cloud.size();
  res.wood.assign(n, 0);
  res.leaf_score.assign(n, 0.0f);
  std::vector<Eigen::Vector3d> pts(n);
  std::vector<std::uint8_t> finite(n, 0);
  std::vector<std::uint32_t> ids;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3f& p = cloud.positions[i];
    pts[i] = Eigen::Vector3d(p.x, p.y, p.z);
    if (!pts[i].allFinite()) continue;
    finite[i] = 1, res.wood[i] = 1;
    ids.push_back(std::uint32_t(i));
    lo = lo.cwiseMin(pts[i]), hi = hi.cwiseMax(pts[i]);
  }
  res.finite_points = ids.size();
  res.threshold = INFINITY;
  if (ids.size() < kMinPoints) {
    res.notes.push_back("too few points to separate leaves from wood: all kept as wood");
    return res;
  }
  const double height = hi.z() - lo.z(), spacing = bsg::median_spacing(pts, ids, true);
  res.scale = o.scale > 0 ? o.scale : std::max(height / 100, 6 * spacing);
  res.spacing = spacing, res.height = height;
  if (!(res.scale > 0) || !std::isfinite(res.scale)) {
    res.notes.push_back("the points have no extent: all kept as wood");
    res.scale = 0;
    return res;
  }

  // 1. Planar at the scale of a leaf, volumetric at the scale of a leaf cluster: the score is
  //    planarity (l2 - l3) / l1 at r / 2 times scattering l3 / l1 at 2r (Demantke et al. 2011,
  //    Eq. 3 and 4). Twigs are linear at r / 2 (low planarity), bark of thick stems is not
  //    scattered at 2r: both score low.
  const std::vector<wood::Eigenfeatures> small = features_at(pts, finite, 0.5 * res.scale);
  const std::vector<wood::Eigenfeatures> large = features_at(pts, finite, 2 * res.scale);

  // 2. Per cell of the fine grid, then smoothed over the graph of cells within r.
  const VoxelSubsample fine = wood::voxel_subsample(pts, finite, res.scale / 4);
  std::vector<double> score(fine.centroids.size(), 0.0);
  for (std::uint32_t i : ids) {
    score[fine.cell[i]] += double(small[i].planarity) * double(large[i].scattering);
  }
  for (std::size_t c = 0; c < score.size(); ++c) score[c] /= double(fine.count[c]);
  const CellGraph graph(fine.centroids, res.scale);
  smooth(graph, o.smoothing_steps, score);

  // 3. Unsupervised decisions: is there a foliage mode at all -- two Gaussians fitted by EM
  //    over the cells' scores (Vicari et al. 2019) must be separated by Ashman's D -- and where
  //    does it start: Otsu's threshold over the same scores. The mixture's own posterior
  //    crossing sits at the narrow low (bark) mode's shoulder on these skewed scores, so it
  //    would take most twigs for leaves; Otsu's between-class criterion does not.
  const wood::Mixture2 m = wood::fit_mixture2(strided(score, kMixtureSamples));
  res.separation = m.separation();
  const wood::OtsuThreshold otsu = wood::otsu_threshold(score);
  res.leaf_mode = res.separation >= o.min_separation && otsu.upper_fraction >= o.min_leaf_share;
  res.upper_share = otsu.upper_fraction;
  if (res.leaf_mode) {
    res.threshold = otsu.threshold;
  } else {
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  "no separate foliage mode in the scan (Ashman's D %.2f, upper class %.0f%%): "
                  "all kept as wood",
                  res.separation, 100 * otsu.upper_fraction);
    res.notes.push_back(buf);
  }

  // 4. Region growing: small wood regions apart from the rest are leaf cards.
  std::vector<std::uint8_t> cell_wood(score.size(), 1);
  if (res.leaf_mode) {
    for (std::size_t c = 0; c < score.size(); ++c) cell_wood[c] = score[c] <= res.threshold;
    drop_small_wood_regions(graph, fine.centroids, 0.5 * res.scale, o.min_region_extent * res.scale,
                            cell_wood);
  }
  for (std::uint32_t i : ids) {
    res.leaf_score[i] = float(score[fine.cell[i]]);
    if (!cell_wood[fine.cell[i]]) {
      res.wood[i] = 0;
      ++res.leaf_points;
    }
  }
  res.leaf_fraction = double(res.leaf_points) / double(res.finite_points);
  return res;
}

PointCloud select_points(const PointCloud& cloud, const std::vector<std::uint8_t>& keep) {
  PointCloud out;
  out.offset = cloud.offset;
  out.scanner = cloud.scanner;
  out.source = cloud.source;
  for (std::size_t i = 0; i < cloud.size() && i < keep.size(); ++i) {
    if (!keep[i]) continue;
    out.positions.push_back(cloud.positions[i]);
    if (!cloud.normals.empty()) out.normals.push_back(cloud.normals[i]);
    if (!cloud.intensity.empty()) out.intensity.push_back(cloud.intensity[i]);
    if (!cloud.classification.empty()) out.classification.push_back(cloud.classification[i]);
  }
  return out;
}

}  // namespace ramus
