#include "backends/scanner/scanner.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "mesh/tree_mesh.h"
#include "backends/scanner/bvh.h"
#include "core/rng.h"

namespace ramus::scanner {

namespace {

// Angular window (azimuth, elevation) covering the box as seen from the station.
struct Window {
  double az0, az1, el0, el1;
};

Window window_of(const Vec3& s, const Vec3& lo, const Vec3& hi) {
  const bool inside = s.x >= lo.x && s.x <= hi.x && s.y >= lo.y && s.y <= hi.y;
  const Vec3 c = (lo + hi) * 0.5;
  const double centre_az = std::atan2(c.y - s.y, c.x - s.x);
  Window w{inside ? -M_PI : 1e9, inside ? M_PI : -1e9, 1e9, -1e9};
  for (int k = 0; k < 8; ++k) {
    const Vec3 p{(k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z};
    const Vec3 d = p - s;
    if (!inside) {
      // Azimuths relative to the centre's, so the window never wraps around +-pi.
      double a = std::atan2(d.y, d.x) - centre_az;
      a = std::remainder(a, 2 * M_PI);
      w.az0 = std::min(w.az0, centre_az + a);
      w.az1 = std::max(w.az1, centre_az + a);
    }
    const double el = std::atan2(d.z, std::hypot(d.x, d.y));
    w.el0 = std::min(w.el0, el);
    w.el1 = std::max(w.el1, el);
  }
  if (inside) w.el0 = -M_PI / 2, w.el1 = M_PI / 2;
  return w;
}

void scan_station(const TriangleBvh& bvh, const Vec3& s, std::uint64_t station,
                  const ScanOptions& o, std::vector<Vec3>& out, std::vector<std::uint32_t>& tris,
                  std::uint64_t& rays) {
  Vec3 lo, hi;
  bvh.bounds(lo, hi);
  const Window w = window_of(s, lo, hi);
  const double range = std::max(distance(s, (lo + hi) * 0.5), 1e-9);
  double step =
      o.angular_step > 0 ? o.angular_step : 1.0 / (std::sqrt(std::max(o.density, 1e-12)) * range);
  const double solid = (w.az1 - w.az0) * (w.el1 - w.el0);
  if (solid / (step * step) > double(o.max_rays)) step = std::sqrt(solid / double(o.max_rays));
  const auto rows = std::size_t(std::ceil((w.el1 - w.el0) / step)) + 1;
  std::vector<std::vector<Vec3>> hits(rows);
  std::vector<std::vector<std::uint32_t>> hit_tris(rows);
  std::vector<std::uint64_t> cast(rows, 0);
  tbb::parallel_for(std::size_t(0), rows, [&](std::size_t r) {
    const double el = w.el0 + double(r) * step;
    // Equal spacing on the sphere: azimuth steps widen by 1/cos(elevation).
    const double az_step = step / std::max(std::cos(el), 1e-3);
    const auto cols = std::size_t(std::ceil((w.az1 - w.az0) / az_step)) + 1;
    for (std::size_t c = 0; c < cols; ++c) {
      const double az = w.az0 + double(c) * az_step;
      const Vec3 d{std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
      ++cast[r];
      Hit h;
      const double limit = o.max_range > 0 ? o.max_range : 1e300;
      if (!bvh.intersect(s, d, 1e-9, limit, h)) continue;
      Rng rng = Rng::stream(o.seed, station, (std::uint64_t(r) << 32) | c);
      if (h.triangle >= o.sparse_from && rng.uniform01() >= o.sparse_keep) continue;
      const double t = o.noise > 0 ? h.t + rng.normal(0, o.noise) : h.t;
      hits[r].push_back(s + d * t);
      hit_tris[r].push_back(h.triangle);
    }
  });
  for (std::size_t r = 0; r < rows; ++r) {
    out.insert(out.end(), hits[r].begin(), hits[r].end());
    tris.insert(tris.end(), hit_tris[r].begin(), hit_tris[r].end());
    rays += cast[r];
  }
}

}  // namespace

ScanResult scan_triangles(const std::vector<Vec3>& vertices,
                          const std::vector<std::uint32_t>& indices, const ScanOptions& o) {
  if (indices.size() < 3) throw ScanError("there is nothing to scan: the mesh has no triangles");
  for (std::uint32_t i : indices) {
    if (i >= vertices.size()) throw ScanError("a triangle index is out of range");
  }
  for (const Vec3& v : vertices) {
    if (!is_finite(v)) throw ScanError("the mesh has a non-finite vertex");
  }
  const TriangleBvh bvh(vertices, indices);
  Vec3 lo, hi;
  bvh.bounds(lo, hi);
  std::vector<Vec3> stations = o.from;
  if (stations.empty()) {
    const double h = std::max(hi.z - lo.z, 1e-6);
    const Vec3 c = (lo + hi) * 0.5;
    stations.push_back({c.x, c.y - 1.5 * h - 0.5 * (hi.y - lo.y), lo.z + 0.015 * h});
  }
  ScanResult res;
  std::vector<Vec3> points;
  for (std::size_t k = 0; k < stations.size(); ++k) {
    if (!is_finite(stations[k])) throw ScanError("a scanner position is not finite");
    scan_station(bvh, stations[k], k, o, points, res.triangle, res.rays);
  }
  res.cloud.offset = Vec3{std::round((lo.x + hi.x) / 2), std::round((lo.y + hi.y) / 2),
                          std::round((lo.z + hi.z) / 2)};
  res.cloud.positions.reserve(points.size());
  for (const Vec3& p : points) res.cloud.positions.push_back(Vec3f(p - res.cloud.offset));
  res.cloud.scanner = stations.front();
  res.cloud.source = "simulated scan";
  return res;
}

namespace {

// The mesh scan_skeleton ray casts.
mesh::TreeMesh scanned_mesh(const Skeleton& skeleton) {
  mesh::MeshOptions mo;
  mo.max_radial_segments = 16;
  return mesh::build_tree_mesh(skeleton, mo);
}

}  // namespace

void append_scanned_triangles(const Skeleton& skeleton, bool leaves, std::vector<Vec3>& vertices,
                              std::vector<std::uint32_t>& indices) {
  const mesh::TreeMesh m = scanned_mesh(skeleton);
  auto append = [&](const mesh::MeshPart& part) {
    const auto base = std::uint32_t(vertices.size());
    // Back to world coordinates in double: a georeferenced tree is meshed about a local origin.
    for (const Vec3f& p : part.positions) vertices.push_back(m.origin + Vec3(p));
    for (std::uint32_t i : part.indices) indices.push_back(base + i);
  };
  append(m.bark);
  if (leaves) {
    append(m.leaves);
    append(m.surfaces);
  }
}

ScanResult scan_skeleton(const Skeleton& skeleton, const ScanOptions& o) {
  std::vector<Vec3> vertices;
  std::vector<std::uint32_t> indices;
  append_scanned_triangles(skeleton, o.leaves, vertices, indices);
  return scan_triangles(vertices, indices, o);
}

std::vector<std::uint8_t> leaf_returns(const Skeleton& skeleton, const ScanResult& scan) {
  // scan_skeleton appends the bark triangles first, then the leaf cards.
  const std::size_t bark = scanned_mesh(skeleton).bark.triangle_count();
  std::vector<std::uint8_t> leaf(scan.triangle.size());
  for (std::size_t i = 0; i < leaf.size(); ++i) leaf[i] = scan.triangle[i] >= bark ? 1 : 0;
  return leaf;
}

Vec3 parse_position(const std::string& text) {
  std::istringstream in(text);
  Vec3 p;
  char c1 = 0, c2 = 0;
  if (!(in >> p.x >> c1 >> p.y >> c2 >> p.z) || c1 != ',' || c2 != ',' || !is_finite(p)) {
    throw ScanError("expected a position as x,y,z, got '" + text + "'");
  }
  std::string rest;
  if (in >> rest) throw ScanError("expected a position as x,y,z, got '" + text + "'");
  return p;
}

}  // namespace ramus::scanner
