// Levels of detail (Burkus et al. 2017, section 4.4): Phong tessellation (Boubekeur & Alexa,
// "Phong Tessellation", SIGGRAPH Asia 2008) adapted to quads. A point of a quad with parameters
// (s, t) is first placed bilinearly, p = sum_i b_i p_i with b = ((1-s)(1-t), s(1-t), st, (1-s)t),
// then projected onto the tangent plane of every corner, pi_i(p) = p - ((p - p_i).n_i) n_i, and
// the projections are blended with the same weights: p* = (1 - alpha) p + alpha sum_i b_i pi_i(p)
// (the paper's equation with barycentric weights replaced by bilinear ones). Normals are the
// normalized bilinear blend of the corner normals.
//
// On an edge two of the weights vanish, so the new points of an edge depend only on the edge's two
// vertices and their normals, symmetrically: two pieces sharing a rim edge (same positions and
// normals, section 4.4) create the same points, and levels that depend only on the edge's
// vertices give both sides the same count.
#include <algorithm>
#include <cmath>
#include <map>

#include "backends/pieces/pieces.h"

namespace ramus::pieces {

namespace {

struct Corner {
  Vec3 p, n;
};

Vec3 phong(const Corner* c, const double* b, int count, double alpha) {
  Vec3 p{0, 0, 0};
  for (int i = 0; i < count; ++i) p += c[i].p * b[i];
  Vec3 proj{0, 0, 0};
  for (int i = 0; i < count; ++i) proj += (p - c[i].n * dot(p - c[i].p, c[i].n)) * b[i];
  return p * (1 - alpha) + proj * alpha;
}

class Tessellator {
 public:
  Tessellator(const PieceMesh& base, int segments, double alpha)
      : in_(base), n_(segments), alpha_(alpha) {
    out_.segments = segments;
    out_.positions = base.positions;
    out_.normals = base.normals;
    out_.uvs = base.uvs;
    out_.joints = base.joints;
    out_.weights = base.weights;
  }

  PieceMesh run() {
    for (std::size_t q = 0; q < in_.quads.size(); ++q) quad(q);
    for (const auto& loop : in_.rim_loops) {
      std::vector<std::uint32_t> l;
      for (std::size_t k = 0; k < loop.size(); ++k) {
        std::uint32_t a = loop[k], b = loop[(k + 1) % loop.size()];
        for (int j = 0; j < n_; ++j) l.push_back(edge_point(a, b, j));
      }
      out_.rim_loops.push_back(std::move(l));
    }
    return std::move(out_);
  }

 private:
  // A new vertex blended from base vertices `v` with weights `b`.
  std::uint32_t add(const std::uint32_t* v, const double* b, int count) {
    Corner c[4];
    for (int i = 0; i < count; ++i) c[i] = {in_.positions[v[i]], in_.normals[v[i]]};
    out_.positions.push_back(phong(c, b, count, alpha_));
    Vec3 n{0, 0, 0};
    std::array<float, 2> uv{0, 0};
    std::map<std::uint16_t, double> w;
    for (int i = 0; i < count; ++i) {
      n += c[i].n * b[i];
      uv[0] += float(in_.uvs[v[i]][0] * b[i]);
      uv[1] += float(in_.uvs[v[i]][1] * b[i]);
      for (int k = 0; k < 4; ++k) {
        if (in_.weights[v[i]][k] > 0) w[in_.joints[v[i]][k]] += in_.weights[v[i]][k] * b[i];
      }
    }
    out_.normals.push_back(normalized(n, c[0].n));
    out_.uvs.push_back(uv);
    // At most four joints: keep the heaviest (ties by joint index), renormalize to sum 1.
    std::vector<std::pair<double, std::uint16_t>> ws;
    for (auto [j, x] : w) {
      if (x > 0) ws.push_back({x, j});
    }
    std::sort(ws.begin(), ws.end(), [](auto a, auto b) {
      return a.first != b.first ? a.first > b.first : a.second < b.second;
    });
    if (ws.size() > 4) ws.resize(4);
    double sum = 0;
    for (auto& e : ws) sum += e.first;
    std::array<std::uint16_t, 4> js{0, 0, 0, 0};
    std::array<float, 4> wf{0, 0, 0, 0};
    for (std::size_t k = 0; k < ws.size(); ++k) {
      js[k] = ws[k].second;
      wf[k] = float(ws[k].first / sum);
    }
    out_.joints.push_back(js);
    out_.weights.push_back(wf);
    return std::uint32_t(out_.positions.size() - 1);
  }

  // Point j (0..n) along edge a -> b. Points are computed once per undirected edge, always from
  // the lower vertex index, so the two quads sharing an edge share its vertices.
  std::uint32_t edge_point(std::uint32_t a, std::uint32_t b, int j) {
    if (j == 0) return a;
    if (j == n_) return b;
    bool flip = a > b;
    std::uint32_t lo = flip ? b : a, hi = flip ? a : b;
    auto it = edges_.find({lo, hi});
    if (it == edges_.end()) {
      std::vector<std::uint32_t> pts;
      for (int k = 1; k < n_; ++k) {
        double t = double(k) / n_;
        std::uint32_t v[2] = {lo, hi};
        double w[2] = {1 - t, t};
        pts.push_back(add(v, w, 2));
      }
      it = edges_.emplace(std::make_pair(lo, hi), std::move(pts)).first;
    }
    int k = flip ? n_ - j : j;
    return it->second[k - 1];
  }

  void quad(std::size_t qi) {
    const auto& q = in_.quads[qi];
    std::vector<std::uint32_t> grid((n_ + 1) * (n_ + 1));
    auto at = [&](int i, int j) -> std::uint32_t& { return grid[j * (n_ + 1) + i]; };
    for (int i = 0; i <= n_; ++i) {
      at(i, 0) = edge_point(q[0], q[1], i);
      at(n_, i) = edge_point(q[1], q[2], i);
      at(n_ - i, n_) = edge_point(q[2], q[3], i);
      at(0, n_ - i) = edge_point(q[3], q[0], i);
    }
    for (int j = 1; j < n_; ++j) {
      for (int i = 1; i < n_; ++i) {
        double s = double(i) / n_, t = double(j) / n_;
        double b[4] = {(1 - s) * (1 - t), s * (1 - t), s * t, (1 - s) * t};
        at(i, j) = add(q.data(), b, 4);
      }
    }
    for (int j = 0; j < n_; ++j) {
      for (int i = 0; i < n_; ++i) {
        out_.quads.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
        out_.quad_tile_type.push_back(in_.quad_tile_type[qi]);
        out_.quad_source.push_back(in_.quad_source[qi]);
      }
    }
  }

  const PieceMesh& in_;
  int n_;
  double alpha_;
  PieceMesh out_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> edges_;
};

}  // namespace

PieceMesh tessellate(const PieceMesh& base, int segments, double alpha) {
  if (segments <= 1) return base;
  return Tessellator(base, segments, alpha).run();
}

int edge_tessellation_level(const Vec3& a, const Vec3& b, const Vec3& camera, int max_level,
                            double near_distance) {
  // (a + b) / 2 is the same whichever vertex comes first; one level less per doubling of the
  // distance beyond near_distance.
  Vec3 mid = (a + b) * 0.5;
  double d = distance(mid, camera) / std::max(near_distance, 1e-12);
  int drop = d <= 1 ? 0 : int(std::floor(std::log2(d)));
  return std::clamp(max_level - drop, 0, max_level);
}

}  // namespace ramus::pieces
