// Generalized cylinders along branch chains: rings of radius r_i swept along the chain's
// polyline with rotation-minimizing frames (frames.h), smooth normals tilted by the taper,
// bark UVs whose v runs along the arc length in units of the local circumference (so a square
// texel stays square), and flat end caps that close every tube.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/rng.h"
#include "mesh/builders.h"
#include "mesh/frames.h"

namespace ramus::mesh {
namespace {

struct Polyline {
  std::vector<Vec3> x;
  std::vector<double> r;
  std::vector<std::uint32_t> node;  // node providing each point
};

// The chain's points with zero-length segments (coincident nodes) merged away, and points
// closer than kMergeShare of the tube's radius to the last one kept: at a tube's scale they are
// one point, and the band between two rings a few millimetres apart folds at the least tilt (two
// nodes 2 mm apart at a reconstructed fork of a 0.56 m trunk cut its radius to 0.15 m). Only the
// coincident ones count as repairs in `merged`.
constexpr double kMergeShare = 0.01;

Polyline chain_polyline(const Skeleton& s, const PreparedSkeleton& p, const Chain& c,
                        std::size_t& merged) {
  Polyline pl;
  const double eps = std::max(p.extent * 1e-9, 1e-12);
  for (std::size_t k = 0; k < c.nodes.size(); ++k) {
    const std::uint32_t n = c.nodes[k];
    const Vec3& pos = s.nodes[n].position;
    // The start of a lateral lies on the parent's axis but takes the lateral's own radius.
    const double r = (k == 0 && c.nodes.size() > 1 && c.parent_chain != kNoChain)
                         ? p.radius[c.nodes[1]]
                         : p.radius[n];
    if (!pl.x.empty() && distance(pl.x.back(), pos) <= eps) {
      ++merged;
      continue;
    }
    if (!pl.x.empty() && distance(pl.x.back(), pos) <= kMergeShare * std::max(pl.r.back(), r))
      continue;
    pl.x.push_back(pos);
    pl.r.push_back(r);
    pl.node.push_back(n);
  }
  return pl;
}

// Two consecutive rings must not cross, or the band between them folds inside out: ring i+1's
// rim lies ahead of ring i's plane when d.t_i >= r_{i+1} sin(a), and ring i's rim behind ring
// i+1's plane when d.t_{i+1} >= r_i sin(a) (d = x_{i+1} - x_i, a the angle between the rings).
// Where a radius breaks that, it is cut to 0.9 of what touches; where the path runs against a
// ring (d.t <= 0: it turns back within the ring's window), to `floor`. The rings are tilted by
// windowed_tangents, so a kink shorter than the radius does not cut it (a reconstructed trunk's
// nodes 20 cm apart and 8-14 cm off its axis made 0.6 m necks of 0.17 m when the rings took the
// bisector of each kink and the radius gave way to the kink's angle).
void limit_radii_between_rings(Polyline& pl, const std::vector<Vec3>& t, double floor) {
  const std::size_t m = pl.x.size();
  std::vector<double> limit(m, std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i + 1 < m; ++i) {
    const Vec3 d = pl.x[i + 1] - pl.x[i];
    const double sin_a = length(cross(t[i], t[i + 1]));
    const double ahead = dot(d, t[i]), behind = dot(d, t[i + 1]);
    if (!(ahead > 0)) limit[i + 1] = 0;
    if (!(behind > 0)) limit[i] = 0;
    if (sin_a > 0) {
      limit[i + 1] = std::min(limit[i + 1], 0.9 * std::max(ahead, 0.0) / sin_a);
      limit[i] = std::min(limit[i], 0.9 * std::max(behind, 0.0) / sin_a);
    }
  }
  for (std::size_t i = 0; i < m; ++i) pl.r[i] = std::min(pl.r[i], std::max(limit[i], floor));
}

// Points that step back against the tube by less than its radius are merged into the point
// before them (at the chain's end the point before the last goes: the end stays where the chain
// meets what grows from it): a tube cannot go backwards, and at its scale such a step is jitter
// of the path (a reconstructed trunk's chain ending 4 cm beyond the fork it ends at, on a 0.27 m
// trunk); kept, the band between the two rings turns inside out and both radii give way (a
// neck). A point steps back when the segment to it runs against the ring before it
// (windowed_tangents). Returns the tangents of what is left.
std::vector<Vec3> merge_steps_back(Polyline& pl) {
  std::vector<Vec3> t = windowed_tangents(pl.x, pl.r);
  for (int pass = 0; pass < 4 && pl.x.size() > 2; ++pass) {
    const std::size_t m = pl.x.size();
    std::vector<std::uint8_t> drop(m, 0);
    bool any = false;
    for (std::size_t i = 1; i < m; ++i) {
      const Vec3 d = pl.x[i] - pl.x[i - 1];
      if (dot(d, t[i - 1]) > 0 || !(length(d) < std::max(pl.r[i - 1], pl.r[i]))) continue;
      const std::size_t k = i + 1 < m ? i : i - 1;  // the chain's end stays
      if (k == 0 || drop[k - 1] || (k + 1 < m && drop[k + 1])) continue;
      drop[k] = 1, any = true;
    }
    if (!any) break;
    Polyline kept;
    for (std::size_t i = 0; i < m; ++i) {
      if (drop[i]) continue;
      kept.x.push_back(pl.x[i]), kept.r.push_back(pl.r[i]), kept.node.push_back(pl.node[i]);
    }
    pl = std::move(kept);
    t = windowed_tangents(pl.x, pl.r);
  }
  return t;
}

int radial_segments(double r, double r_max, const TubeParams& tp) {
  const double f = r_max > 0 ? std::sqrt(std::clamp(r / r_max, 0.0, 1.0)) : 1.0;
  return std::clamp(int(std::ceil(tp.max_segments * f)), tp.min_segments,
                    std::max(tp.min_segments, tp.max_segments));
}

Vec3f to_f(const Vec3& v) { return Vec3f(v); }

void add_cap(MeshPart& out, std::uint32_t ring, int n, const Vec3& center, const Vec3& normal,
             bool at_end, std::array<float, 4> wind) {
  const std::uint32_t c = std::uint32_t(out.positions.size());
  out.positions.push_back(to_f(center));
  out.normals.push_back(to_f(normal));
  out.uvs.push_back({0.5f, 0.5f});
  out.wind.push_back(wind);
  out.skin_node.push_back(out.skin_node[ring]);
  for (int j = 0; j < n; ++j) {
    const double a = 2 * std::numbers::pi * j / n;
    const Vec3f q = out.positions[ring + j];  // the same floats: welds exactly to the ring
    const std::array<float, 4> w = out.wind[ring + j];
    out.positions.push_back(q);
    out.normals.push_back(to_f(normal));
    out.uvs.push_back({float(0.5 + 0.5 * std::cos(a)), float(0.5 + 0.5 * std::sin(a))});
    out.wind.push_back(w);
    out.skin_node.push_back(out.skin_node[ring + j]);
  }
  for (int j = 0; j < n; ++j) {
    const std::uint32_t a = c + 1 + j, b = c + 1 + (j + 1) % n;
    if (at_end) {
      out.indices.insert(out.indices.end(), {c, a, b});
    } else {
      out.indices.insert(out.indices.end(), {c, b, a});
    }
  }
}

}  // namespace

float WindField::main_bend(double z) const {
  if (height <= 0) return 0.0f;
  const double h = std::clamp((z - base_z) / height, 0.0, 1.0);
  return float(h * h);  // bends most at the top, like a cantilever's deflection
}

WindField make_wind_field(const Skeleton& s, const PreparedSkeleton& p) {
  WindField w;
  w.base_z = p.lo.z;
  w.height = p.hi.z - p.lo.z;
  w.node_branch.assign(s.nodes.size(), 0.0f);
  w.chain_phase.resize(p.chains.size());
  for (std::size_t c = 0; c < p.chains.size(); ++c) {
    const Chain& ch = p.chains[c];
    w.chain_phase[c] = float(Rng::stream(0x77696e64, ch.nodes.front(), c).uniform01());
    if (ch.parent_chain == kNoChain) continue;  // the trunk does not take part in branch bending
    double total = 0;
    for (std::size_t k = 1; k < ch.nodes.size(); ++k) {
      total += distance(s.nodes[ch.nodes[k]].position, s.nodes[ch.nodes[k - 1]].position);
    }
    double along = 0;
    for (std::size_t k = 1; k < ch.nodes.size(); ++k) {
      along += distance(s.nodes[ch.nodes[k]].position, s.nodes[ch.nodes[k - 1]].position);
      w.node_branch[ch.nodes[k]] = total > 0 ? float(along / total) : 1.0f;
    }
  }
  return w;
}

bool add_chain_tube(const Skeleton& s, const PreparedSkeleton& p, std::uint32_t id,
                    const WindField& wind, const TubeParams& tp, MeshPart& out,
                    MeshReport& report) {
  const Chain& chain = p.chains[id];
  std::size_t merged = 0;
  Polyline pl = chain_polyline(s, p, chain, merged);
  if (tp.count_repairs) report.merged_nodes += merged;
  if (pl.x.size() < 2) return false;
  const auto t = merge_steps_back(pl);
  const std::size_t m = pl.x.size();
  limit_radii_between_rings(pl, t, p.min_radius);
  const auto& first = s.nodes[pl.node[std::min<std::size_t>(1, m - 1)]];
  const auto ref = rotation_minimizing_frames(pl.x, t, first.left);
  const int n = radial_segments(*std::max_element(pl.r.begin(), pl.r.end()), p.max_radius, tp);
  const std::uint32_t base = std::uint32_t(out.positions.size());
  const float phase = wind.chain_phase[id];
  double v = 0;
  for (std::size_t i = 0; i < m; ++i) {
    if (i > 0) v += distance(pl.x[i], pl.x[i - 1]) / (std::numbers::pi * (pl.r[i] + pl.r[i - 1]));
    // Taper slope dr/ds tilts the normal so shading follows the cone, not a cylinder.
    const std::size_t a = i > 0 ? i - 1 : i, b = i + 1 < m ? i + 1 : i;
    // Clamped: a radius jump over a vanishing distance must not overflow the normal.
    const double slope =
        std::clamp((pl.r[b] - pl.r[a]) / std::max(distance(pl.x[b], pl.x[a]), 1e-300), -1e3, 1e3);
    const Vec3 bin = cross(t[i], ref[i]);
    const float branch =
        i == 0 && chain.parent_chain != kNoChain ? 0.0f : wind.node_branch[pl.node[i]];
    for (int j = 0; j <= n; ++j) {
      const double ang = 2 * std::numbers::pi * (j % n) / n;  // j == n repeats j == 0 (UV seam)
      const Vec3 radial = ref[i] * std::cos(ang) + bin * std::sin(ang);
      out.positions.push_back(to_f(pl.x[i] + radial * pl.r[i]));
      out.normals.push_back(to_f(normalized(radial - t[i] * slope, radial)));
      out.uvs.push_back({float(j) / float(n), float(v)});
      out.wind.push_back({wind.main_bend(out.positions.back().z), branch, phase, 0.0f});
      out.skin_node.push_back(pl.node[i]);
    }
  }
  const std::uint32_t stride = std::uint32_t(n + 1);
  for (std::uint32_t i = 0; i + 1 < m; ++i) {
    for (std::uint32_t j = 0; j < std::uint32_t(n); ++j) {
      const std::uint32_t a = base + i * stride + j, b = a + 1, c = a + stride, d = c + 1;
      out.indices.insert(out.indices.end(), {a, b, d, a, d, c});
    }
  }
  if (tp.caps) {
    add_cap(out, base, n, pl.x[0], -t[0], false, out.wind[base]);
    add_cap(out, base + std::uint32_t(m - 1) * stride, n, pl.x[m - 1], t[m - 1], true,
            out.wind[base + (m - 1) * stride]);
  }
  return true;
}

}  // namespace ramus::mesh
