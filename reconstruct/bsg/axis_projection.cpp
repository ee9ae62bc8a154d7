#include "reconstruct/bsg/axis_projection.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>

#include "reconstruct/bsg/kdtree.h"

namespace ramus::bsg {

namespace {

// Weighted centroids of points on a grid of edge `cell`; cell_of[i] is the cell of point i.
// Cells are ordered by grid key, so the result does not depend on any hash order.
struct Level {
  std::vector<Eigen::Vector3d> pos;
  std::vector<double> weight;
  std::vector<std::uint32_t> cell_of;
};

Level coarsen(const std::vector<Eigen::Vector3d>& pos, const std::vector<std::uint32_t>& counts,
              double cell) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  for (const auto& p : pos) lo = lo.cwiseMin(p);
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
  keyed.reserve(pos.size());
  auto q = [](double x) { return std::uint64_t(std::clamp(x, 0.0, 2097151.0)); };
  for (std::uint32_t i = 0; i < pos.size(); ++i) {
    const Eigen::Vector3d c = ((pos[i] - lo) / cell).array().floor();
    keyed.emplace_back((q(c.z()) << 42) | (q(c.y()) << 21) | q(c.x()), i);
  }
  std::sort(keyed.begin(), keyed.end());
  Level level;
  level.cell_of.assign(pos.size(), kNone);
  for (std::size_t i = 0; i < keyed.size();) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    double w = 0;
    std::size_t j = i;
    for (; j < keyed.size() && keyed[j].first == keyed[i].first; ++j) {
      const double c = counts[keyed[j].second];
      sum += c * pos[keyed[j].second];
      w += c;
      level.cell_of[keyed[j].second] = std::uint32_t(level.pos.size());
    }
    level.pos.push_back(sum / w);
    level.weight.push_back(w);
    i = j;
  }
  return level;
}

struct Line {
  Eigen::Vector3d point, dir;
  bool found = false;
};

// The line of the ball around q on level l, if the ball is linear.
Line fit_line(const Level& l, const PointIndex& index, const Eigen::Vector3d& q, double reach,
              std::size_t k, const AxisProjectionParams& params, std::uint32_t* ids, double* d2) {
  const std::size_t m = index.knn_within(q, k, reach, ids, d2);
  double w = 0;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < m; ++i)
    w += l.weight[ids[i]], mean += l.weight[ids[i]] * l.pos[ids[i]];
  if (w < params.min_weight || m < 3) return {};
  mean /= w;
  // The weighted scatter in scalars, entry (a, b) being d_b (w d_a) as Eigen's
  // `w * d * d.transpose()` computes it (the same bits): an Eigen outer product added per point
  // goes through a stack temporary whose stores and wider loads stall the loop.
  double c[9] = {};  // column-major, as Eigen stores it
  for (std::size_t i = 0; i < m; ++i) {
    const Eigen::Vector3d d = l.pos[ids[i]] - mean;
    const double wi = l.weight[ids[i]];
    const double wd[3] = {wi * d.x(), wi * d.y(), wi * d.z()};
    for (int b = 0; b < 3; ++b) {
      for (int a = 0; a < 3; ++a) c[a + 3 * b] += d(b) * wd[a];
    }
  }
  const Eigen::Matrix3d cov = Eigen::Map<const Eigen::Matrix3d>(c);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(cov / w);
  const Eigen::Vector3d lambda = eig.eigenvalues();  // ascending
  if (lambda(2) < params.linearity * lambda(1)) return {};
  // The branch's axis is the principal line through the ball's centroid.
  return {mean, eig.eigenvectors().col(2), true};
}

}  // namespace

std::size_t project_to_axes(Graph& graph, double voxel, const AxisProjectionParams& params) {
  const std::size_t n = graph.size();
  if (n < 3 || !(voxel > 0)) return 0;
  const int levels = std::clamp(params.levels, 1, 12);
  const std::size_t k = std::max<std::size_t>(4, params.neighbours);
  // Level j: cells of 2^(j+1) voxels, balls of `ball` cells. A cell gets the line of the ball
  // around its centroid (when that ball is linear), refitted from the centroid's projection on
  // it, where the ball is centred on the branch. Each vertex takes the line of the finest level
  // whose ball around its cell is linear, so the ball grows with the branch's thickness; cells
  // of a coarser level are fitted only when they hold a vertex that no finer level placed.
  const std::vector<Eigen::Vector3d> samples = graph.pos;
  std::vector<std::uint8_t> placed(n, 0);
  std::size_t moved = 0;
  for (int j = 0; j < levels && moved < n; ++j) {
    const double cell = voxel * double(2 << j);
    const Level l = coarsen(samples, graph.points, cell);
    std::vector<std::uint8_t> wanted(l.pos.size(), 0);
    for (std::uint32_t v = 0; v < n; ++v) {
      if (!placed[v]) wanted[l.cell_of[v]] = 1;
    }
    const PointIndex index(l.pos);
    std::vector<Line> lines(l.pos.size());
    tbb::parallel_for(
        tbb::blocked_range<std::uint32_t>(0, std::uint32_t(l.pos.size()), 512),
        [&](const tbb::blocked_range<std::uint32_t>& r) {
          std::vector<std::uint32_t> ids(k);
          std::vector<double> d2(k);
          for (std::uint32_t c = r.begin(); c != r.end(); ++c) {
            if (!wanted[c]) continue;
            const double reach = params.ball * cell;
            Line line = fit_line(l, index, l.pos[c], reach, k, params, ids.data(), d2.data());
            for (int pass = 1; pass < params.passes && line.found; ++pass) {
              const Eigen::Vector3d q = line.point + line.dir * line.dir.dot(l.pos[c] - line.point);
              const Line again = fit_line(l, index, q, reach, k, params, ids.data(), d2.data());
              if (!again.found) break;
              line = again;
            }
            lines[c] = line;
          }
        });
    // The vertex moves onto the line, keeping its place along the branch.
    for (std::uint32_t v = 0; v < n; ++v) {
      const Line& line = lines[l.cell_of[v]];
      if (placed[v] || !line.found) continue;
      graph.pos[v] = line.point + line.dir * line.dir.dot(samples[v] - line.point);
      placed[v] = 1;
      ++moved;
    }
  }
  return moved;
}

}  // namespace ramus::bsg
