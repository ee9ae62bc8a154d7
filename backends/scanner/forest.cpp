#include "backends/scanner/forest.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/rng.h"

namespace ramus::scanner {

double crown_radius(const Skeleton& tree) {
  const std::vector<std::uint32_t> roots = tree.roots();
  if (roots.empty()) return 0;
  const Vec3 base = tree.nodes[roots.front()].position;
  double r = 0;
  for (const SkeletonNode& n : tree.nodes) {
    r = std::max(r, std::hypot(n.position.x - base.x, n.position.y - base.y));
  }
  return r;
}

Skeleton plant(const Skeleton& tree, double x, double y) {
  Skeleton out = tree;
  const std::vector<std::uint32_t> roots = tree.roots();
  if (roots.empty()) return out;
  const Vec3 root = tree.nodes[roots.front()].position;
  const Vec3 shift{x - root.x, y - root.y, -root.z};
  for (SkeletonNode& n : out.nodes) n.position = n.position + shift;
  for (OrganAnchor& o : out.organs) o.position = o.position + shift;
  return out;
}

std::vector<Vec3> place_trees(const std::vector<double>& radii, const PlotArea& area,
                              std::uint64_t seed, int attempts) {
  std::vector<Vec3> placed;
  for (std::size_t i = 0; i < radii.size(); ++i) {
    // Random sequential adsorption: uniform tries until one keeps its distance to every tree
    // placed before it.
    Rng rng = Rng::stream(seed, 0x706c6f74 /* "plot" */, i);
    bool done = false;
    for (int a = 0; a < attempts && !done; ++a) {
      const Vec3 p{rng.uniform(0, area.width), rng.uniform(0, area.depth), 0};
      done = std::all_of(placed.begin(), placed.end(), [&](const Vec3& q) {
        const std::size_t j = std::size_t(&q - placed.data());
        return std::hypot(p.x - q.x, p.y - q.y) >= std::max(radii[i], radii[j]);
      });
      if (done) placed.push_back(p);
    }
    if (!done) {
      char msg[300];
      std::snprintf(msg, sizeof msg,
                    "tree %zu of %zu finds no place at least a crown radius (%.2f) from the "
                    "others in %g x %g after %d tries: use a larger --area or fewer trees",
                    i + 1, radii.size(), radii[i], area.width, area.depth, attempts);
      throw ScanError(msg);
    }
  }
  return placed;
}

std::vector<Vec3> station_grid(const PlotArea& area, const std::vector<Vec3>& bases,
                               const ForestScanOptions& o) {
  const int nx = std::max(1, int(std::lround(area.width / o.station_spacing)));
  const int ny = std::max(1, int(std::lround(area.depth / o.station_spacing)));
  const double sx = area.width / nx, sy = area.depth / ny;
  auto clear = [&](double x, double y) {
    return std::all_of(bases.begin(), bases.end(),
                       [&](const Vec3& b) { return std::hypot(x - b.x, y - b.y) >= o.clearance; });
  };
  std::vector<Vec3> stations;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      double x = (i + 0.5) * sx, y = (j + 0.5) * sy;
      // A surveyor sets the tripod beside a trunk, not in it: search rings of growing radius.
      for (int ring = 1; !clear(x, y) && ring <= 20; ++ring) {
        for (int k = 0; k < 8; ++k) {
          const double a = k * M_PI / 4, d = ring * 0.5 * o.clearance;
          const double cx = (i + 0.5) * sx + d * std::cos(a), cy = (j + 0.5) * sy + d * std::sin(a);
          if (clear(cx, cy)) {
            x = cx, y = cy;
            break;
          }
        }
      }
      stations.push_back({x, y, o.station_height});
    }
  }
  return stations;
}

ScanResult scan_forest(const std::vector<Skeleton>& planted, const PlotArea& area,
                       const ForestScanOptions& o) {
  std::vector<Vec3> vertices, bases;
  std::vector<std::uint32_t> indices;
  double margin = 0;
  for (const Skeleton& t : planted) {
    append_scanned_triangles(t, o.scan.leaves, vertices, indices);
    const std::vector<std::uint32_t> roots = t.roots();
    if (!roots.empty()) bases.push_back(t.nodes[roots.front()].position);
    margin = std::max(margin, crown_radius(t));
  }
  // The ground: two triangles, last, so their hits are told apart by triangle index.
  const auto ground_triangle = std::uint32_t(indices.size() / 3);
  const auto g = std::uint32_t(vertices.size());
  vertices.push_back({-margin, -margin, 0});
  vertices.push_back({area.width + margin, -margin, 0});
  vertices.push_back({area.width + margin, area.depth + margin, 0});
  vertices.push_back({-margin, area.depth + margin, 0});
  for (std::uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u}) indices.push_back(g + k);
  ScanOptions so = o.scan;
  so.from = station_grid(area, bases, o);
  so.sparse_from = ground_triangle;
  so.sparse_keep = o.ground_keep;
  ScanResult out = scan_triangles(vertices, indices, so);
  out.cloud.source = "simulated forest plot";
  return out;
}

}  // namespace ramus::scanner
