#include "reconstruct/bsg/chain_cylinders.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "reconstruct/bsg/bsg.h"
#include "reconstruct/bsg/cylinder_fit.h"

namespace ramus::bsg {

namespace {

// A branch whose fitted radius is above this share of the stem's below it is taken for one of
// two co-dominant stems of a fork, not for a side branch (bridge_unfitted; the value was chosen
// over the one-station harness trees turned to six azimuths, README, *Centre lines*).
constexpr double kCoDominant = 0.85;

struct Piece {
  std::vector<std::uint32_t> nodes;  // along the chain
  double radius = 0;                 // the chain's radius estimate
};

double median(std::vector<double> a) {
  if (a.empty()) return 0;
  const auto mid = a.begin() + std::ptrdiff_t(a.size() / 2);
  std::nth_element(a.begin(), mid, a.end());
  return *mid;
}

// Chains (from a fork's child to the next fork or tip, the fork included as the last node) cut
// into pieces of about `max(3 r, 6 spacings)`, r the chain's median radius (fitted, else hint).
std::vector<Piece> pieces_of_chains(const std::vector<Eigen::Vector3d>& pos,
                                    const std::vector<std::uint32_t>& parent,
                                    const std::vector<double>& hint,
                                    const std::vector<std::uint8_t>& fitted,
                                    const std::vector<double>& fitted_radius, double spacing,
                                    double thin) {
  const std::size_t n = pos.size();
  std::vector<int> children(n, 0);
  std::vector<std::uint32_t> only_child(n, kNone);
  for (std::uint32_t v = 0; v < n; ++v) {
    if (parent[v] < n) ++children[parent[v]], only_child[parent[v]] = v;
  }
  std::vector<Piece> out;
  std::vector<std::uint32_t> chain;
  for (std::uint32_t s = 0; s < n; ++s) {
    if (parent[s] < n && children[parent[s]] == 1) continue;  // not a chain start
    chain.clear();
    for (std::uint32_t v = s;; v = only_child[v]) {
      chain.push_back(v);
      if (children[v] != 1) break;
    }
    std::vector<double> radii;
    bool any_unfitted = false;
    for (std::uint32_t v : chain) {
      radii.push_back(fitted[v] ? fitted_radius[v] : hint[v]);
      any_unfitted |= !fitted[v] && children[v] < 2 && hint[v] >= thin;
    }
    if (!any_unfitted) continue;
    const double r = std::max(median(radii), 2 * spacing);
    const double length = std::max(3 * r, 6 * spacing);
    Piece piece;
    piece.radius = r;
    double along = 0;
    for (std::size_t k = 0; k < chain.size(); ++k) {
      if (k > 0) along += (pos[chain[k]] - pos[chain[k - 1]]).norm();
      piece.nodes.push_back(chain[k]);
      if (along >= length && k + 1 < chain.size()) {
        out.push_back(piece);
        piece.nodes.clear();
        along = 0;
      }
    }
    if (!piece.nodes.empty()) out.push_back(piece);
  }
  return out;
}

}  // namespace

// A node between two fitted nodes (at most `steps` nodes away on either side, downwards along
// the heaviest child) that neither its cross-section nor a cylinder placed lies on the segment
// between them: the BSG's nodes on a thick limb are a few radii apart, and one node left on the
// bark (often a fork where a spur leaves) makes a detour of a radius across the limb. Near the
// base of a side branch (the fitted node below is on its parent stem) the node goes onto the
// branch's own axis instead.
std::size_t bridge_unfitted(std::vector<Eigen::Vector3d>& pos,
                            const std::vector<std::uint32_t>& parent,
                            const std::vector<double>& hint, std::vector<std::uint8_t>& fitted,
                            std::vector<double>& fitted_radius, double spacing, double thin,
                            int steps) {
  const std::size_t n = pos.size();
  std::vector<std::vector<std::uint32_t>> ch(n);
  std::vector<std::uint32_t> order;
  for (std::uint32_t v = 0; v < n; ++v) {
    if (parent[v] < n) {
      ch[parent[v]].push_back(v);
    } else {
      order.push_back(v);
    }
  }
  for (std::size_t i = 0; i < order.size(); ++i) {
    for (std::uint32_t c : ch[order[i]]) order.push_back(c);
  }
  std::vector<std::size_t> size(n, 1);
  for (std::size_t i = order.size(); i-- > 0;) {
    if (parent[order[i]] < n) size[parent[order[i]]] += size[order[i]];
  }
  auto heaviest = [&](std::uint32_t v) {
    std::uint32_t best = kNone;
    for (std::uint32_t c : ch[v]) {
      if (best == kNone || size[c] > size[best]) best = c;
    }
    return best;
  };
  // The child the stem continues into: the heaviest, unless its branch is fitted thinner than
  // the pipe model lets a stem's continuation be (kPipeChild of the nearest fitted radius at or
  // below the fork, within `steps` nodes) and another child's branch is not, and runs straighter
  // on from the stem below; then the thickest such. A child's radius is the first fitted one
  // within `steps` nodes up its heaviest chain, its direction the way from the fork to that node,
  // the stem's the way from `steps` nodes down to the fork. The subtree's node count stands for
  // its wood (Livny et al. 2010, 4.3), but a limb full of hanging twigs outweighs the leader it
  // leaves (the weeping tree grown from seed 1, one station: a 10 cm limb outweighed the 14 cm
  // leader at 5.8 m, and the leader's nodes were bridged onto the chord from the trunk to the
  // limb, up to 0.9 r off).
  auto measured_up = [&](std::uint32_t c) {
    for (int k = 0; k <= steps && c != kNone; ++k, c = heaviest(c)) {
      if (fitted[c]) return c;
    }
    return kNone;
  };
  std::vector<std::uint32_t> stem_child(n, kNone);
  for (std::uint32_t v = 0; v < n; ++v) {
    stem_child[v] = heaviest(v);
    if (ch[v].size() < 2 || parent[v] >= n) continue;
    double below = 0;
    std::uint32_t down = v;
    for (int k = 0; k < steps && parent[down] < n; ++k) {
      if (!(below > 0) && fitted[down]) below = fitted_radius[down];
      down = parent[down];
    }
    if (!(below > 0) && fitted[down]) below = fitted_radius[down];
    const Eigen::Vector3d stem = (pos[v] - pos[down]).normalized();
    const std::uint32_t h = measured_up(stem_child[v]);
    if (!(below > 0) || h == kNone || fitted_radius[h] >= kPipeChild * below) continue;
    const double straight_h = stem.dot((pos[h] - pos[v]).normalized());
    double thickest = fitted_radius[h];
    for (std::uint32_t c : ch[v]) {
      const std::uint32_t m = measured_up(c);
      if (m == kNone || !(fitted_radius[m] > thickest) || fitted_radius[m] < kPipeChild * below)
        continue;
      if (!(stem.dot((pos[m] - pos[v]).normalized()) > straight_h)) continue;
      thickest = fitted_radius[m], stem_child[v] = c;
    }
  }
  std::vector<std::uint32_t> moved;
  std::vector<Eigen::Vector3d> to;
  std::vector<double> radius;
  for (std::uint32_t v = 0; v < n; ++v) {
    if (fitted[v] || ch[v].empty() || parent[v] >= n || hint[v] < thin) continue;
    // `side`: the way down to a leaves v's branch for the stem it grows from.
    std::uint32_t a = parent[v], b = stem_child[v];
    bool side = stem_child[a] != v;
    for (int k = 0; k < steps && !fitted[a] && parent[a] < n; ++k) {
      side |= stem_child[parent[a]] != a;
      a = parent[a];
    }
    for (int k = 0; k < steps && !fitted[b] && !ch[b].empty(); ++k) b = stem_child[b];
    if (!fitted[a] || !fitted[b]) continue;
    const Eigen::Vector3d ab = pos[b] - pos[a];
    const double l2 = ab.squaredNorm();
    if (!(l2 > 0)) continue;
    const double t = std::clamp((pos[v] - pos[a]).dot(ab) / l2, 0.0, 1.0);
    Eigen::Vector3d on = pos[a] + t * ab;
    double r = fitted_radius[a] + t * (fitted_radius[b] - fitted_radius[a]);
    if (side && fitted_radius[b] <= kCoDominant * fitted_radius[a]) {
      // The chord from a (on the stem's axis, below where the branch leaves) to b cuts the
      // corner of the crotch; the branch's own axis runs straight on into the stem (TreeQSM's
      // cylinders continue a branch to its parent). So v goes onto the line through b and the
      // next fitted node out along the branch, at least a radius beyond b, no farther back
      // from b than a is. Not at a fork of two stems of about the same thickness, where the
      // heaviest child need not be the one that continues the stem below.
      std::uint32_t c = b;
      bool found = false;
      for (int k = 0; k < steps && !found && !ch[c].empty(); ++k) {
        c = stem_child[c];
        found = fitted[c] && (pos[c] - pos[b]).norm() >= fitted_radius[b];
      }
      if (found) {
        const Eigen::Vector3d back = (pos[b] - pos[c]).normalized();
        on = pos[b] + std::clamp((pos[v] - pos[b]).dot(back), 0.0, std::sqrt(l2)) * back;
        r = fitted_radius[b];
      }
    }
    if ((on - pos[v]).norm() > 1.5 * r + 2 * spacing) continue;
    moved.push_back(v), to.push_back(on), radius.push_back(r);
  }
  for (std::size_t k = 0; k < moved.size(); ++k) {
    pos[moved[k]] = to[k], fitted[moved[k]] = 1, fitted_radius[moved[k]] = radius[k];
  }
  return moved.size();
}

std::size_t fit_chain_cylinders(std::vector<Eigen::Vector3d>& pos,
                                const std::vector<std::uint32_t>& parent,
                                const std::vector<double>& hint, std::vector<std::uint8_t>& fitted,
                                std::vector<double>& fitted_radius, const PointIndex& index,
                                const std::vector<Eigen::Vector3d>& samples,
                                const std::vector<double>& weight, const CentreLineParams& p,
                                double noise) {
  const std::size_t n = pos.size();
  std::vector<int> children(n, 0);
  for (std::uint32_t v = 0; v < n; ++v) {
    if (parent[v] < n) ++children[parent[v]];
  }
  // Twigs are left alone, as by the cross-sections (CentreLineParams::min_hint_spacings): a twig's
  // piece gathers its parent's bark and would move onto the parent's axis.
  const double thin = p.min_hint_spacings * p.spacing;
  // No branch is thicker than the thickest cross-section (the trunk's) by much.
  double r_max = 0;
  for (std::size_t v = 0; v < n; ++v) {
    if (fitted[v]) r_max = std::max(r_max, fitted_radius[v]);
  }
  const std::vector<Piece> pieces =
      pieces_of_chains(pos, parent, hint, fitted, fitted_radius, p.spacing, thin);
  std::vector<std::uint8_t> placed(n, 0);
  std::vector<double> placed_radius(n, 0.0);
  std::vector<Eigen::Vector3d> placed_pos(n);
  // A node the fit may place: not fitted yet, not a fork, not a twig.
  auto movable = [&](std::uint32_t v) { return !fitted[v] && children[v] < 2 && hint[v] >= thin; };
  tbb::parallel_for(std::size_t(0), pieces.size(), [&](std::size_t k) {
    const Piece& piece = pieces[k];
    // A chain is cut into pieces when any of its nodes is movable; a piece without one would be
    // fitted for nothing (a third of the pieces of pytlidar_tree_1).
    if (std::none_of(piece.nodes.begin(), piece.nodes.end(), movable)) return;
    const std::uint32_t first = piece.nodes.front(), last = piece.nodes.back();
    // The start line: through the piece's middle, from the node before it to its last node.
    const std::uint32_t before = parent[first] < n ? parent[first] : first;
    Eigen::Vector3d d0 = pos[last] - pos[before];
    if (!(d0.norm() > 0)) return;
    d0.normalize();
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (std::uint32_t v : piece.nodes) centre += pos[v];
    centre /= double(piece.nodes.size());
    const double half_length = 0.5 * (pos[last] - pos[before]).norm();
    double r0 = piece.radius;
    thread_local std::vector<std::uint32_t> near;  // per-thread work space
    thread_local std::vector<Eigen::Vector3d> pts;
    thread_local std::vector<double> w;
    for (int attempt = 0; attempt < 6; ++attempt) {
      const double reach = std::max(2.5 * r0, 5 * p.spacing);
      const double span = std::max({half_length, r0, 3 * p.spacing});
      gather_cylinder(centre, d0, reach, span, index, samples, weight, near, pts, w);
      if (pts.size() < 12) return;
      const std::size_t cap = 4 * std::size_t(p.max_slab_points) / 3;
      if (pts.size() > cap) {
        const std::size_t stride = (pts.size() + cap - 1) / cap;
        std::size_t m = 0;
        for (std::size_t i = 0; i < pts.size(); i += stride) pts[m] = pts[i], w[m] = w[i], ++m;
        pts.resize(m), w.resize(m);
      }
      const CylinderFit f = fit_cylinder(pts, w, centre, d0, span, noise);
      if (!f.valid) return;
      const Eigen::Vector3d off = f.point - centre;
      const double shift = (off - off.dot(f.direction) * f.direction).norm();
      // The cylinder reaches beyond the gathering: gather wider, unless its axis is already
      // farther from the chain than any accepted one may be (a twig's piece that found its
      // parent: the wider gathering finds the same parent, at the same angle, and is rejected;
      // two thirds of the regrowths on pytlidar_tree_1 were these).
      const double max_angle_any = 40.0;
      if (shift + f.radius > 0.9 * reach && attempt < 5) {
        if (std::abs(f.direction.dot(d0)) < std::cos(max_angle_any * M_PI / 180)) return;
        r0 = std::min(2 * r0, 1.3 * std::max(f.radius, shift));
        // A gathering wider than the trunk only collects other branches.
        if (r_max > 0 && r0 > p.max_growth * r_max + p.spacing) return;
        continue;
      }
      // A cylinder much thicker than the chain's estimate is either the limb under a spur chain
      // on its bark (the chain runs along it) or the parent of a twig (the twig leaves it at an
      // angle): only the first is accepted (15 degrees: 40 let the bundled broadleaf's twigs
      // onto their parents, precision within 2 x radius 0.966 instead of 0.978).
      const double max_angle = f.radius > 1.5 * piece.radius ? 15.0 : max_angle_any;
      const bool good = f.coverage >= p.min_coverage && f.inlier_fraction >= p.min_inliers &&
                        f.residual <= p.max_residual * f.radius + noise && f.radius >= p.spacing &&
                        f.axial_fill >= 0.6 &&
                        std::abs(f.direction.dot(d0)) >= std::cos(max_angle * M_PI / 180) &&
                        shift + f.radius <= reach &&
                        (r_max <= 0 || f.radius <= p.max_growth * r_max + p.spacing);
      if (!good) return;
      for (std::uint32_t v : piece.nodes) {
        if (!movable(v)) continue;
        const Eigen::Vector3d x = pos[v];
        const Eigen::Vector3d a = f.point + (x - f.point).dot(f.direction) * f.direction;
        // The piece's nodes lie on the bark of the branch they stand for or inside it; a node
        // outside the cylinder belongs to another branch (a limb's node beside the trunk).
        if ((x - a).norm() > 1.15 * f.radius + 2 * p.spacing) continue;
        placed[v] = 1, placed_pos[v] = a, placed_radius[v] = f.radius;
      }
      return;
    }
  });
  std::size_t count = 0;
  for (std::size_t v = 0; v < n; ++v) {
    if (!placed[v]) continue;
    pos[v] = placed_pos[v], fitted[v] = 1, fitted_radius[v] = placed_radius[v];
    ++count;
  }
  return count + bridge_unfitted(pos, parent, hint, fitted, fitted_radius, p.spacing, thin);
}

}  // namespace ramus::bsg
