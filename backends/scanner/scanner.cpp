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

// One return of a beam: its range along the beam's centre line and the triangle that made it.
struct Echo {
  double range;
  std::uint32_t triangle;
};

// The echoes of the beam along d (azimuth az, elevation el) from s (ScanOptions, "The beam"):
// seven rays through its footprint, the centre and six on the circle that halves the area of
// the ring outside the centre's share (radius sqrt((1 + 1/7) / 2) of the footprint's), each an
// equal share of the footprint; their hits grouped along the beam; one echo per group covering
// enough of the footprint, at the group's mean range. `hits` is scratch.
void beam_echoes(const TriangleBvh& bvh, const Vec3& s, const Vec3& d, double az, double el,
                 const ScanOptions& o, double limit, std::vector<Echo>& hits,
                 std::vector<Echo>& echoes) {
  constexpr int kRays = 7;
  const double ring = std::sqrt((1.0 + 1.0 / kRays) / 2.0);
  const Vec3 e1{-std::sin(az), std::cos(az), 0.0};
  const Vec3 e2{-std::sin(el) * std::cos(az), -std::sin(el) * std::sin(az), std::cos(el)};
  hits.clear();
  for (int k = 0; k < kRays; ++k) {
    Vec3 across{0, 0, 0};
    if (k > 0) {
      const double a = (k - 1) * M_PI / 3;
      across = (e1 * std::cos(a) + e2 * std::sin(a)) * ring;
    }
    const Vec3 origin = s + across * (0.5 * o.beam_diameter);
    const Vec3 dir = normalized(d + across * (0.5 * o.beam_divergence));
    Hit h;
    if (!bvh.intersect(origin, dir, 1e-9, limit, h)) continue;
    hits.push_back({dot(origin + dir * h.t - s, d), h.triangle});
  }
  std::sort(hits.begin(), hits.end(), [](const Echo& a, const Echo& b) {
    return a.range < b.range || (a.range == b.range && a.triangle < b.triangle);
  });
  for (std::size_t i = 0; i < hits.size();) {
    std::size_t j = i + 1;
    while (j < hits.size() &&
           (o.range_resolution <= 0 || hits[j].range - hits[j - 1].range < o.range_resolution))
      ++j;
    if (double(j - i) >= o.min_echo_fraction * kRays) {
      double sum = 0;
      for (std::size_t k = i; k < j; ++k) sum += hits[k].range;
      const double mean = sum / double(j - i);
      // The triangle of the hit nearest the mean stands for the echo (leaf or bark).
      std::size_t best = i;
      for (std::size_t k = i; k < j; ++k) {
        if (std::abs(hits[k].range - mean) < std::abs(hits[best].range - mean)) best = k;
      }
      echoes.push_back({mean, hits[best].triangle});
    }
    i = j;
  }
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
  const bool beam = o.beam_divergence > 0 || o.beam_diameter > 0;
  std::vector<std::vector<Vec3>> hits(rows);
  std::vector<std::vector<std::uint32_t>> hit_tris(rows);
  std::vector<std::uint64_t> cast(rows, 0);
  tbb::parallel_for(std::size_t(0), rows, [&](std::size_t r) {
    const double el = w.el0 + double(r) * step;
    // Equal spacing on the sphere: azimuth steps widen by 1/cos(elevation).
    const double az_step = step / std::max(std::cos(el), 1e-3);
    const auto cols = std::size_t(std::ceil((w.az1 - w.az0) / az_step)) + 1;
    std::vector<Echo> echoes, footprint;
    for (std::size_t c = 0; c < cols; ++c) {
      const double az = w.az0 + double(c) * az_step;
      const Vec3 d{std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
      ++cast[r];
      const double limit = o.max_range > 0 ? o.max_range : 1e300;
      echoes.clear();
      if (beam) {
        beam_echoes(bvh, s, d, az, el, o, limit, footprint, echoes);
      } else {
        Hit h;
        if (bvh.intersect(s, d, 1e-9, limit, h)) echoes.push_back({h.t, h.triangle});
      }
      if (echoes.empty()) continue;
      Rng rng = Rng::stream(o.seed, station, (std::uint64_t(r) << 32) | c);
      for (const Echo& e : echoes) {
        if (e.triangle >= o.sparse_from && rng.uniform01() >= o.sparse_keep) continue;
        const double t = o.noise > 0 ? e.range + rng.normal(0, o.noise) : e.range;
        hits[r].push_back(s + d * t);
        hit_tris[r].push_back(e.triangle);
      }
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
  for (const double v :
       {o.noise, o.beam_divergence, o.beam_diameter, o.range_resolution, o.registration_error}) {
    if (!(v >= 0) || !std::isfinite(v)) {
      throw ScanError("the noise, beam and registration settings must be finite and not negative");
    }
  }
  if (!(o.min_echo_fraction > 0 && o.min_echo_fraction <= 1)) {
    throw ScanError("the least share of a footprint that returns an echo must be in (0, 1]");
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
    const std::size_t first = points.size();
    scan_station(bvh, stations[k], k, o, points, res.triangle, res.rays);
    if (k > 0 && o.registration_error > 0) {
      // One rigid shift per station, from its own stream (no ray of the station uses it).
      Rng rng = Rng::stream(o.seed, k, ~std::uint64_t(0));
      const Vec3 shift{rng.normal(0, o.registration_error), rng.normal(0, o.registration_error),
                       rng.normal(0, o.registration_error)};
      for (std::size_t i = first; i < points.size(); ++i) points[i] = points[i] + shift;
    }
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
