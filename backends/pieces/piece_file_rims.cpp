// Pieces from files (glTF or OBJ): turning a quad mesh with named rims into a piece draft.
//
// Rims are given as vertex loops named `rim:<name>` (docs/pieces.md); `rim:root` is required. Each
// loop must be a regular hexagon (within 1e-3 of its radius); its first vertex is corner 0. The
// whole mesh is moved by the similarity that takes its root rim onto the canonical root rim
// (section 4.2: "the root rim of all models has the same orientation and size"), and the rim
// vertices are snapped exactly onto their hexagons so that pieces interlock to rounding.
#include <algorithm>
#include <cmath>
#include <map>

#include "backends/pieces/piece_build.h"

namespace ramus::pieces {

namespace {

constexpr double kHexTolerance = 1e-3;

struct Frame {
  Trs trs;  // canonical rim -> this rim
};

// The similarity taking the canonical rim onto the hexagon `p` (corner k -> p[k]). The growth
// axis is the normal of the loop's counter-clockwise order.
Trs hexagon_frame(const std::string& path, const std::string& rim, const std::array<Vec3, 6>& p) {
  Vec3 c{0, 0, 0};
  for (const Vec3& v : p) c += v / 6.0;
  double radius = 0;
  for (const Vec3& v : p) radius += distance(v, c) / 6.0;
  if (!(radius > 1e-12)) throw PiecesError(path + ": rim:" + rim + " has no extent");
  Vec3 x = normalized(p[0] - c);
  Vec3 z = normalized(cross(p[0] - c, p[1] - c));
  Vec3 y = cross(z, x);
  for (int k = 0; k < 6; ++k) {
    double a = M_PI / 3 * k;
    Vec3 want = c + (x * std::cos(a) + y * std::sin(a)) * radius;
    if (distance(want, p[k]) > kHexTolerance * radius) {
      throw PiecesError(path + ": rim:" + rim + " is not a regular hexagon (vertex " +
                        std::to_string(k) + " is " + std::to_string(distance(want, p[k]) / radius) +
                        " radii off)");
    }
  }
  // Rotation from the columns x, y, z (Shepperd's method, via the largest diagonal term).
  double m00 = x.x, m11 = y.y, m22 = z.z, tr = m00 + m11 + m22;
  Quat q;
  if (tr > 0) {
    double s = std::sqrt(tr + 1) * 2;
    q = {0.25 * s, (y.z - z.y) / s, (z.x - x.z) / s, (x.y - y.x) / s};
  } else if (m00 > m11 && m00 > m22) {
    double s = std::sqrt(1 + m00 - m11 - m22) * 2;
    q = {(y.z - z.y) / s, 0.25 * s, (y.x + x.y) / s, (z.x + x.z) / s};
  } else if (m11 > m22) {
    double s = std::sqrt(1 + m11 - m00 - m22) * 2;
    q = {(z.x - x.z) / s, (y.x + x.y) / s, 0.25 * s, (z.y + y.z) / s};
  } else {
    double s = std::sqrt(1 + m22 - m00 - m11) * 2;
    q = {(x.y - y.x) / s, (z.x + x.z) / s, (z.y + y.z) / s, 0.25 * s};
  }
  return Trs{c, q.normalized(), radius};
}

}  // namespace

PieceDraft draft_from_raw(const std::string& name, const std::string& path,
                          std::vector<Vec3> positions,
                          std::vector<std::array<std::uint32_t, 4>> quads,
                          std::vector<RawRim> rims) {
  if (quads.empty()) throw PiecesError(path + ": the piece has no quads");
  for (const auto& q : quads) {
    for (std::uint32_t v : q) {
      if (v >= positions.size()) throw PiecesError(path + ": a quad names a missing vertex");
    }
  }
  auto root_it =
      std::find_if(rims.begin(), rims.end(), [](const RawRim& r) { return r.name == "root"; });
  if (root_it == rims.end()) throw PiecesError(path + ": the piece has no rim named rim:root");
  std::rotate(rims.begin(), root_it, root_it + 1);  // root first, leaves in file order
  Vec3 centroid{0, 0, 0};
  for (const Vec3& p : positions) centroid += p / double(positions.size());

  std::vector<Trs> frames;
  for (RawRim& r : rims) {
    if (r.vertices.size() == 7 && r.vertices.front() == r.vertices.back()) r.vertices.pop_back();
    if (r.vertices.size() != 6) {
      throw PiecesError(path + ": rim:" + r.name + " has " + std::to_string(r.vertices.size()) +
                        " vertices; every rim is a hexagon of 6");
    }
    std::array<Vec3, 6> p;
    for (int k = 0; k < 6; ++k) {
      if (r.vertices[k] >= positions.size()) {
        throw PiecesError(path + ": rim:" + r.name + " names a missing vertex");
      }
      p[k] = positions[r.vertices[k]];
    }
    Trs f = hexagon_frame(path, r.name, p);
    // The root rim's axis points into the piece, a leaf rim's out of it; a loop given the other
    // way round is reversed (corner 0 stays).
    bool into = dot(centroid - f.t, f.r.rotate({0, 0, 1})) > 0;
    if (into != (r.name == "root")) {
      std::reverse(r.vertices.begin() + 1, r.vertices.end());
      for (int k = 0; k < 6; ++k) p[k] = positions[r.vertices[k]];
      f = hexagon_frame(path, r.name, p);
    }
    frames.push_back(f);
  }
  // Move everything so the root rim is canonical.
  Trs to_canonical = frames[0].inverse();
  for (Vec3& p : positions) p = to_canonical.point(p);
  for (Trs& f : frames) f = to_canonical * f;
  frames[0] = Trs{};

  PieceDraft d;
  d.type.name = name;
  d.type.kind = PieceKind::Mesh;
  d.mesh.positions = positions;
  d.mesh.normals.assign(positions.size(), Vec3{0, 0, 1});
  d.fixed_normal.assign(positions.size(), 0);
  d.mesh.quads = std::move(quads);
  std::vector<int> rim_of(positions.size(), -1);
  for (std::size_t r = 0; r < rims.size(); ++r) {
    Rim rim;
    rim.name = rims[r].name;
    rim.building = frames[r];
    rim.joint = std::uint16_t(r);
    for (int k = 0; k < 6; ++k) {
      std::uint32_t v = rims[r].vertices[k];
      if (rim_of[v] >= 0) throw PiecesError(path + ": a vertex belongs to two rims");
      rim_of[v] = int(r);
      rim.corners[k] = v;
      d.mesh.positions[v] = rim.building.point(canonical_corner(k));
      d.mesh.normals[v] = rim.building.r.rotate(canonical_corner_normal(k));
      d.fixed_normal[v] = 1;
    }
    if (r == 0) {
      d.type.root = rim;
    } else {
      d.type.leaves.push_back(rim);
    }
  }
  // Rim vertices follow their rim's joint alone; the others blend the nearest rims' joints by
  // inverse squared distance to the rim centres (at most four).
  for (std::size_t v = 0; v < positions.size(); ++v) {
    std::array<std::uint16_t, 4> j{0, 0, 0, 0};
    std::array<float, 4> w{0, 0, 0, 0};
    if (rim_of[v] >= 0) {
      j[0] = std::uint16_t(rim_of[v]);
      w[0] = 1;
    } else {
      std::vector<std::pair<double, std::uint16_t>> c;
      for (std::size_t r = 0; r < frames.size(); ++r) {
        double dd = std::max(
            1e-12, dot(d.mesh.positions[v] - frames[r].t, d.mesh.positions[v] - frames[r].t));
        c.push_back({1 / dd, std::uint16_t(r)});
      }
      std::sort(c.begin(), c.end(), [](auto a, auto b) {
        return a.first != b.first ? a.first > b.first : a.second < b.second;
      });
      if (c.size() > 4) c.resize(4);
      double sum = 0;
      for (auto& e : c) sum += e.first;
      for (std::size_t k = 0; k < c.size(); ++k) {
        j[k] = c[k].second;
        w[k] = float(c[k].first / sum);
      }
    }
    d.mesh.joints.push_back(j);
    d.mesh.weights.push_back(w);
    d.mesh.uvs.push_back({0, 0});
  }
  return d;
}

PieceDraft draft_mesh_file(const std::string& name, const std::string& path,
                           const std::string* bytes) {
  std::string ext = path.substr(
      path.find_last_of('.') == std::string::npos ? path.size() : path.find_last_of('.'));
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return std::tolower(ch); });
  if (ext == ".obj") return draft_obj_file(name, path, bytes);
  if (ext == ".gltf" || ext == ".glb") return draft_gltf_file(name, path, bytes);
  throw PiecesError(path + ": a piece file is .gltf, .glb or .obj");
}

}  // namespace ramus::pieces
