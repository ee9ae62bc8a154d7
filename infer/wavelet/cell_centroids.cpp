// Centroids of the points in the cells of every dyad (cell_centroids.h).
#include "infer/wavelet/cell_centroids.h"

#include <algorithm>
#include <cmath>

namespace ramus::wavelet {
namespace {

std::uint64_t key(std::int64_t x, std::int64_t y, std::int64_t z) {
  return std::uint64_t(x) | (std::uint64_t(y) << 21) | (std::uint64_t(z) << 42);
}
std::array<int, 3> unkey(std::uint64_t k) {
  const std::uint64_t m = (std::uint64_t(1) << 21) - 1;
  return {int(k & m), int((k >> 21) & m), int((k >> 42) & m)};
}

// The voxel a coordinate falls in, clamped like voxelize() so that every point has a voxel.
int voxel_of(double coordinate, double size, std::size_t n) {
  const double c = coordinate / size;
  if (!(c >= 1)) return 0;
  return c >= double(n - 1) ? int(n - 1) : int(c);
}

}  // namespace

CellCentroids::CellCentroids(const AlignedCloud& cloud, const VoxelGrid& grid) : grid_(grid) {
  // The finest dyad (L - 1) from the points: through a dense array when it is small (up to
  // 64^3 cells, a 128^3 grid), hashing only its occupied cells; hashing every point otherwise.
  const int top = std::max(0, grid.levels - 1);
  levels_.resize(std::size_t(top) + 1);
  auto& finest = levels_.back();
  const std::int64_t side = std::int64_t(1) << top;
  if (side * side * side <= (std::int64_t(1) << 18)) {
    std::vector<Sum> dense(std::size_t(side * side * side));
    for (const Vec3& p : cloud.points) {
      const auto c = cell_of(top, p);
      Sum& s = dense[std::size_t(c[0] + side * (c[1] + side * c[2]))];
      s.sum += p;
      ++s.count;
    }
    for (std::int64_t i = 0; i < std::int64_t(dense.size()); ++i) {
      if (dense[std::size_t(i)].count == 0) continue;
      finest.emplace(key(i % side, i / side % side, i / (side * side)), dense[std::size_t(i)]);
    }
  } else {
    finest.reserve(cloud.points.size() / 4 + 16);
    for (const Vec3& p : cloud.points) {
      const auto c = cell_of(top, p);
      Sum& s = finest[key(c[0], c[1], c[2])];
      s.sum += p;
      ++s.count;
    }
  }
  for (int j = top; j-- > 0;) {
    auto& coarse = levels_[std::size_t(j)];
    coarse.reserve(levels_[std::size_t(j) + 1].size() / 2 + 16);
    for (const auto& [k, s] : levels_[std::size_t(j) + 1]) {
      const auto c = unkey(k);
      Sum& t = coarse[key(c[0] >> 1, c[1] >> 1, c[2] >> 1)];
      t.sum += s.sum;
      t.count += s.count;
    }
  }
}

std::optional<Vec3> CellCentroids::centroid(int level, const std::array<int, 3>& cell) const {
  if (level < 0 || level >= int(levels_.size())) return std::nullopt;
  for (int k = 0; k < 3; ++k) {
    if (cell[k] < 0 || cell[k] >= (1 << level)) return std::nullopt;
  }
  const auto& m = levels_[std::size_t(level)];
  const auto it = m.find(key(cell[0], cell[1], cell[2]));
  if (it == m.end()) return std::nullopt;
  return it->second.sum / double(it->second.count);
}

Vec3 CellCentroids::centre(int level, const std::array<int, 3>& cell) const {
  const double size = grid_.voxel_size * double(grid_.n) / double(std::int64_t(1) << level);
  Vec3 local;
  for (int k = 0; k < 3; ++k) local[k] = double(cell[k]) + 0.5;
  return grid_.origin + local * size;
}

std::array<int, 3> CellCentroids::cell_of(int level, const Vec3& p) const {
  const Vec3 q = p - grid_.origin;
  const int shift = grid_.levels - level;
  return {voxel_of(q.x, grid_.voxel_size, grid_.n) >> shift,
          voxel_of(q.y, grid_.voxel_size, grid_.n) >> shift,
          voxel_of(q.z, grid_.voxel_size, grid_.n) >> shift};
}

}  // namespace ramus::wavelet
