// Leaving out isolated points (isolated_points.h).
#include "infer/wavelet/isolated_points.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace ramus::wavelet {

std::optional<AlignedCloud> without_isolated_points(const AlignedCloud& cloud) {
  std::size_t removed = 0;
  if (cloud.points.empty()) return std::nullopt;
  Vec3 lo = cloud.points[0], hi = cloud.points[0];
  for (const Vec3& p : cloud.points) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  if (!(extent > 0)) return std::nullopt;
  // A dense count grid: one pass, no hashing (the inference of a 64^3 grid takes milliseconds).
  constexpr int n = kIsolationCells;
  const double size = extent * (1 + 1e-9) / n;
  auto cell = [&](double v, double low) { return std::clamp(int((v - low) / size), 0, n - 1); };
  std::vector<std::uint32_t> count(std::size_t(n) * n * n, 0);
  std::vector<std::uint32_t> index(cloud.points.size());
  for (std::size_t i = 0; i < cloud.points.size(); ++i) {
    const Vec3& p = cloud.points[i];
    index[i] = std::uint32_t(cell(p.x, lo.x) + n * (cell(p.y, lo.y) + n * cell(p.z, lo.z)));
    ++count[index[i]];
  }
  std::vector<char> isolated(cloud.points.size(), 0);
  for (std::size_t i = 0; i < cloud.points.size(); ++i) {
    // The root (III-A's lowest point, the origin) stays: the tree is grown from it.
    if (count[index[i]] > 1 || cloud.points[i].z <= 0) continue;
    const int x = int(index[i] % n), y = int(index[i] / n % n), z = int(index[i] / (n * n));
    std::uint32_t around = 0;
    for (int dz = -1; dz <= 1; ++dz) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int a = x + dx, b = y + dy, c = z + dz;
          if (a < 0 || b < 0 || c < 0 || a >= n || b >= n || c >= n) continue;
          around += count[std::size_t(a + n * (b + n * c))];
        }
      }
    }
    if (around <= 1) {
      isolated[i] = 1;
      ++removed;
    }
  }
  if (removed == 0) return std::nullopt;
  AlignedCloud out;
  out.alignment = cloud.alignment;
  out.points.reserve(cloud.points.size() - removed);
  for (std::size_t i = 0; i < cloud.points.size(); ++i) {
    if (!isolated[i]) out.points.push_back(cloud.points[i]);
  }
  return out;
}

}  // namespace ramus::wavelet
