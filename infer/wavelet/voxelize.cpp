#include "infer/wavelet/voxelize.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ramus::wavelet {

VoxelValues parse_voxel_values(const std::string& word) {
  if (word == "occupancy") return VoxelValues::occupancy;
  if (word == "density") return VoxelValues::density;
  throw std::invalid_argument("unknown voxel values '" + word +
                              "' (expected occupancy or density)");
}

const char* to_string(VoxelValues v) {
  return v == VoxelValues::occupancy ? "occupancy" : "density";
}

namespace {

std::size_t cell(double coordinate, double size, std::size_t n) {
  double c = std::floor(coordinate / size);
  // Clamping only absorbs rounding at the far faces; the cube holds every point by construction.
  if (!(c > 0)) return 0;
  return std::min(n - 1, std::size_t(c));
}

}  // namespace

VoxelGrid voxelize(const AlignedCloud& cloud, const VoxelizeOptions& options) {
  if (cloud.points.empty()) throw std::invalid_argument("the point cloud is empty");
  VoxelGrid grid(options.levels);
  Vec3 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
          std::numeric_limits<double>::max()};
  Vec3 hi = -lo;
  for (const Vec3& p : cloud.points) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  double side = std::max(extent * (1 + 1e-9), options.min_extent);
  grid.voxel_size = side / double(grid.n);
  grid.origin = {(lo.x + hi.x - side) / 2, (lo.y + hi.y - side) / 2, lo.z};

  for (const Vec3& p : cloud.points) {
    Vec3 q = p - grid.origin;
    grid.at(cell(q.x, grid.voxel_size, grid.n), cell(q.y, grid.voxel_size, grid.n),
            cell(q.z, grid.voxel_size, grid.n)) += 1.0;
  }
  if (options.values == VoxelValues::occupancy) {
    for (double& v : grid.values) v = v > 0 ? 1.0 : 0.0;
  } else {
    double most = *std::max_element(grid.values.begin(), grid.values.end());
    for (double& v : grid.values) v /= most;
  }
  return grid;
}

PointCloud voxel_centres(const VoxelGrid& grid, double threshold, const Alignment* alignment) {
  PointCloud out;
  out.offset = alignment ? alignment->root : Vec3{};
  for (std::size_t z = 0; z < grid.n; ++z) {
    for (std::size_t y = 0; y < grid.n; ++y) {
      for (std::size_t x = 0; x < grid.n; ++x) {
        if (!(grid.at(x, y, z) > threshold)) continue;
        Vec3 p = grid.centre(double(x), double(y), double(z));
        if (alignment) p = alignment->to_world(p);
        out.positions.push_back(Vec3f(p - out.offset));
      }
    }
  }
  return out;
}

}  // namespace ramus::wavelet
