// The built-in parametric pieces (Burkus et al. 2017, section 4.1): I (a slightly narrowing
// tube), Y (a symmetric fork with co-dominant stems), Psi (a trifurcation, planar or 3D) and the
// branch-stem attachment piece.
//
// All share one construction, a hub: the root rim (the canonical hexagon), its collar ring on the
// universal rim cone (section 4.4), a hexagonal "top loop" T0..T5, then one branch per leaf rim.
// With one branch the top loop is the branch's base. With two, the diagonal T0-T3 becomes a
// raised ridge T0-C1-C2-T3 and each half of the hexagon plus the ridge is a six-vertex loop; with
// three, ridges run from a raised centre C to T1, T3 and T5. A branch is a band of quads from its
// base loop through a middle ring and a collar ring (on the rim cone again) to its leaf rim,
// which is the canonical rim carried by the rim's building transform (a similarity, 4.2).
#include <algorithm>
#include <cmath>

#include "backends/pieces/piece_build.h"

namespace ramus::pieces {

Vec3 canonical_corner(int k) {
  double a = M_PI / 3 * k;
  return {std::cos(a), std::sin(a), 0};
}
Vec3 canonical_corner_normal(int k) {
  double a = M_PI / 3 * k;
  return normalized(Vec3{std::cos(a), std::sin(a), kRimConeSlope});
}
Vec3 canonical_collar(int k, double z) {
  double a = M_PI / 3 * k, r = 1 - z * kRimConeSlope;
  return {r * std::cos(a), r * std::sin(a), z};
}

namespace {

constexpr double kCollar = 0.35;  // distance of a collar ring from its rim, in rim radii

struct BranchSpec {
  std::string rim;
  Vec3 direction;  // unit
  double length;   // from the base loop's centre to the leaf rim's centre
  double scale;    // leaf rim radius relative to the root rim
};

// Builds vertices with their blending parameter: `u` runs from 0 at the root rim to 1 at the
// leaf rims; a vertex belongs to one or more branches (its terminal weight u is shared).
class HubBuilder {
 public:
  HubBuilder(std::string name, PieceKind kind) {
    d_.type.name = std::move(name);
    d_.type.kind = kind;
    d_.type.root.name = "root";
  }

  std::uint32_t vertex(const Vec3& p, double u, std::vector<int> branches, double uv_u,
                       double uv_v) {
    d_.mesh.positions.push_back(p);
    d_.mesh.normals.push_back({0, 0, 1});
    d_.fixed_normal.push_back(0);
    d_.mesh.uvs.push_back({float(uv_u), float(uv_v)});
    std::array<std::uint16_t, 4> j{0, 0, 0, 0};
    std::array<float, 4> w{float(1 - u), 0, 0, 0};
    for (std::size_t b = 0; b < branches.size() && b < 3; ++b) {
      j[b + 1] = std::uint16_t(1 + branches[b]);
      w[b + 1] = float(u / double(branches.size()));
    }
    if (u >= 1) w[0] = 0;
    d_.mesh.joints.push_back(j);
    d_.mesh.weights.push_back(w);
    return std::uint32_t(d_.mesh.positions.size() - 1);
  }
  void fix_normal(std::uint32_t v, const Vec3& n) {
    d_.mesh.normals[v] = n;
    d_.fixed_normal[v] = 1;
  }
  // Quads between two rings of six, each counter-clockwise about the local axis.
  void band(const std::array<std::uint32_t, 6>& lo, const std::array<std::uint32_t, 6>& hi) {
    for (int k = 0; k < 6; ++k) {
      int n = (k + 1) % 6;
      d_.mesh.quads.push_back({lo[k], lo[n], hi[n], hi[k]});
    }
  }
  PieceDraft& draft() { return d_; }

 private:
  PieceDraft d_;
};

// The rotation about `axis` (after taking +z onto it) that best aligns the canonical corners
// with the given loop, so the quads between loop and rim are not twisted.
Trs rim_building(const std::array<Vec3, 6>& loop, const Vec3& centre, const Vec3& axis,
                 double scale) {
  Quat tilt = Quat::between({0, 0, 1}, axis);
  double sx = 0, sy = 0;
  for (int k = 0; k < 6; ++k) {
    Vec3 d = tilt.conjugate().rotate(loop[k] - centre);  // in the tilted frame
    double a = std::atan2(d.y, d.x) - M_PI / 3 * k;
    sx += std::cos(a);
    sy += std::sin(a);
  }
  double psi = std::atan2(sy, sx);
  return Trs{centre, (tilt * Quat::axis_angle({0, 0, 1}, psi)).normalized(), scale};
}

PieceDraft build_hub(const std::string& name, PieceKind kind, double top_height, double top_radius,
                     double ridge, const std::vector<BranchSpec>& branches) {
  HubBuilder h(name, kind);
  const int n = int(branches.size());
  // The root collar moves with the root joint alone: the cone at the joint keeps its shape.
  const double u_top = n == 1 ? 0.5 : 0.4;
  std::vector<int> all(n);
  for (int b = 0; b < n; ++b) all[b] = b;

  // Which branches each top-loop corner belongs to.
  std::array<std::vector<int>, 6> owner;
  for (int k = 0; k < 6; ++k) {
    if (n == 1) owner[k] = {0};
    if (n == 2)
      owner[k] = (k == 0 || k == 3) ? std::vector<int>{0, 1} : std::vector<int>{k < 3 ? 0 : 1};
    if (n == 3) {
      owner[k] =
          (k % 2 == 0) ? std::vector<int>{k / 2} : std::vector<int>{(k - 1) / 2, ((k + 1) / 2) % 3};
    }
  }

  std::array<std::uint32_t, 6> root, collar, top;
  for (int k = 0; k < 6; ++k) {
    root[k] = h.vertex(canonical_corner(k), 0, owner[k], k / 6.0, 0);
    h.fix_normal(root[k], canonical_corner_normal(k));
    h.draft().type.root.corners[k] = root[k];
  }
  h.draft().type.root.joint = 0;
  for (int k = 0; k < 6; ++k)
    collar[k] = h.vertex(canonical_collar(k, kCollar), 0, owner[k], k / 6.0, 0.1);
  std::array<Vec3, 6> tp;
  for (int k = 0; k < 6; ++k) {
    Vec3 c = canonical_corner(k);
    tp[k] = {c.x * top_radius, c.y * top_radius, top_height};
    top[k] = h.vertex(tp[k], u_top, owner[k], k / 6.0, 0.35);
  }
  h.band(root, collar);
  h.band(collar, top);

  // Base loops of the branches.
  std::vector<std::array<std::uint32_t, 6>> base(n);
  if (n == 1) {
    base[0] = top;
  } else if (n == 2) {
    Vec3 up{0, 0, top_height + ridge};
    Vec3 c1 = tp[0] * (2.0 / 3) + tp[3] * (1.0 / 3), c2 = tp[0] * (1.0 / 3) + tp[3] * (2.0 / 3);
    c1.z = c2.z = up.z;
    std::uint32_t v1 = h.vertex(c1, 0.45, all, 0.5, 0.45), v2 = h.vertex(c2, 0.45, all, 0.5, 0.45);
    base[0] = {top[0], top[1], top[2], top[3], v2, v1};
    base[1] = {top[3], top[4], top[5], top[0], v1, v2};
  } else {
    Vec3 c{0, 0, top_height + ridge};
    std::uint32_t vc = h.vertex(c, 0.45, all, 0.5, 0.45);
    std::array<std::uint32_t, 6> m{};
    for (int k = 1; k < 6; k += 2) {
      Vec3 p = tp[k] * 0.5 + c * 0.5;
      p.z += ridge * 0.15;
      m[k] = h.vertex(p, 0.43, owner[k], k / 6.0, 0.42);
    }
    for (int b = 0; b < 3; ++b) {
      int lo = (2 * b + 5) % 6, mid = 2 * b, hi = 2 * b + 1;
      base[b] = {top[lo], top[mid], top[hi], m[hi], vc, m[lo]};
    }
  }

  // Branches: base -> (middle ring) -> collar -> leaf rim.
  for (int b = 0; b < n; ++b) {
    const BranchSpec& s = branches[b];
    std::array<Vec3, 6> bp;
    Vec3 centre{0, 0, 0};
    for (int k = 0; k < 6; ++k) {
      bp[k] = h.draft().mesh.positions[base[b][k]];
      centre += bp[k] / 6.0;
    }
    Rim rim;
    rim.name = s.rim;
    rim.building = rim_building(bp, centre + s.direction * s.length, s.direction, s.scale);
    rim.joint = std::uint16_t(1 + b);
    std::array<std::uint32_t, 6> col, leaf, mid;
    for (int k = 0; k < 6; ++k) {
      col[k] =
          h.vertex(rim.building.point(canonical_collar(k, -kCollar)), 0.88, {b}, k / 6.0, 0.85);
      leaf[k] = h.vertex(rim.building.point(canonical_corner(k)), 1, {b}, k / 6.0, 1);
      h.fix_normal(leaf[k], rim.building.r.rotate(canonical_corner_normal(k)));
      rim.corners[k] = leaf[k];
    }
    std::array<std::uint32_t, 6> from = base[b];
    if (n > 1) {
      for (int k = 0; k < 6; ++k) {
        Vec3 p = bp[k] * 0.5 + h.draft().mesh.positions[col[k]] * 0.5;
        mid[k] = h.vertex(p, 0.7, {b}, k / 6.0, 0.65);
      }
      h.band(from, mid);
      from = mid;
    }
    h.band(from, col);
    h.band(col, leaf);
    h.draft().type.leaves.push_back(rim);
  }
  return std::move(h.draft());
}

Vec3 tilted(double azimuth_deg, double tilt_deg) {
  double a = azimuth_deg * M_PI / 180, t = tilt_deg * M_PI / 180;
  return {std::sin(t) * std::cos(a), std::sin(t) * std::sin(a), std::cos(t)};
}

}  // namespace

PieceDraft draft_tube(const std::string& name, const TubeParams& p) {
  double h = p.length / 2;
  return build_hub(name, PieceKind::Tube, h, 0.5 * (1 + p.taper), 0,
                   {{"top", {0, 0, 1}, p.length - h, p.taper}});
}

// The fork's halves are the hexagon sides around azimuth 90 (left) and 270 (right): the fork
// lies in the y-z plane.
PieceDraft draft_fork(const std::string& name, const ForkParams& p) {
  double h = p.length * 0.3;
  return build_hub(name, PieceKind::Fork, h, 0.95, 0.45,
                   {{"left", tilted(90, p.angle), p.length * 0.7, p.taper},
                    {"right", tilted(270, p.angle), p.length * 0.7, p.taper}});
}

// Thirds of the hexagon around azimuths 0 (left), 120 (middle) and 240 (right). Planar: the
// middle branch goes straight up and the others lean to azimuths 30 and 210, one plane with it;
// 3D: all three lean by `angle` at their own azimuths.
PieceDraft draft_trifurcation(const std::string& name, const TrifurcationParams& p) {
  double h = p.length * 0.3;
  std::vector<BranchSpec> b;
  if (p.planar) {
    b = {{"left", tilted(30, p.angle), p.length * 0.7, p.taper},
         {"middle", tilted(0, 0), p.length * 0.7, p.taper},
         {"right", tilted(210, p.angle), p.length * 0.7, p.taper}};
  } else {
    b = {{"left", tilted(0, p.angle), p.length * 0.7, p.taper},
         {"middle", tilted(120, p.angle), p.length * 0.7, p.taper},
         {"right", tilted(240, p.angle), p.length * 0.7, p.taper}};
  }
  return build_hub(name, PieceKind::Trifurcation, h, 0.95, 0.45, b);
}

// A stem that goes on (rim "stem", slightly narrowing) with a thinner branch leaving it at
// `angle` (rim "branch", radius `branch`): the fork construction with unequal halves.
PieceDraft draft_attachment(const std::string& name, const AttachmentParams& p) {
  double h = p.length * 0.35;
  return build_hub(name, PieceKind::Attachment, h, 0.95, 0.3,
                   {{"stem", tilted(90, 6), p.length * 0.65, p.taper},
                    {"branch", tilted(270, p.angle), p.length * 0.45, p.branch}});
}

}  // namespace ramus::pieces
