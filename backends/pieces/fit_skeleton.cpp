// Fitting pieces to a skeleton (Burkus et al. 2017, sections 4.2-4.3): every internode becomes a
// tube piece (I), every fork of two a fork piece (Y), a fork of three a trifurcation (Psi) when
// the set has one, else a chain of Ys. Asymmetric forks come "with just appropriate scalings in
// bone transformations" (4.1): only terminal joints are changed. A terminal joint's local
// transform is the similarity that carries the child's root rim to where the skeleton wants it
// (the next node, along the next segment, with that segment's radius), so each piece is aimed,
// stretched (interior vertices blend between root and terminal joint) and scaled by its bones;
// root joints stay rigid, so the rims still interlock exactly.
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "backends/pieces/piece_build.h"
#include "core/rng.h"

namespace ramus::pieces {

namespace {

constexpr Vec3 kAxis{0, 0, 1};

struct Task {
  bool fork = false;  // a fork at `node` (children `group`) or a segment ending at `node`
  std::uint32_t node = 0;
  std::vector<std::uint32_t> group;  // fork: the children still to serve
  std::uint32_t parent = kNone;      // placed piece and leaf rim it hangs from
  std::uint32_t leaf = 0;
  Trs target;  // wanted world frame of the new piece's root rim
};

class Fitter {
 public:
  Fitter(const PieceSet& set, const Skeleton& sk, const FitOptions& opt)
      : set_(set), sk_(sk), opt_(opt), ch_(sk.children()) {
    for (std::uint32_t i = 0; i < set.types.size(); ++i) {
      const PieceType& t = set.types[i];
      if (t.lods.empty()) continue;
      if (t.kind == PieceKind::Tube && t.leaves.size() == 1 && tube_ == kNone) tube_ = i;
      if (t.kind == PieceKind::Fork && fork_ == kNone) fork_ = i;
      if (t.kind == PieceKind::Trifurcation && psi_ == kNone) psi_ = i;
    }
    if (tube_ == kNone) throw PiecesError("fitting a skeleton needs a tube piece (I)");
    if (fork_ == kNone) throw PiecesError("fitting a skeleton needs a fork piece (Y)");
    Vec3 lo, hi;
    sk.bounds(lo, hi);
    min_radius_ = std::max(1e-6, distance(lo, hi) * 1e-4);
  }

  Tree run() {
    std::uint32_t root = pick_root();
    std::uint32_t nc = ch_.count(root);
    if (nc == 0) throw PiecesError("the skeleton has no segment to fit");
    const Vec3 p = sk_.nodes[root].position;
    Vec3 dir = nc == 1 ? direction(p, sk_.nodes[*ch_.begin(root)].position, kAxis)
                       : mean_direction(root, {ch_.begin(root), ch_.end(root)}, kAxis);
    double r = nc == 1 ? radius(*ch_.begin(root)) : radius_at_fork(root);
    Trs start{p, Quat::between(kAxis, dir), r};
    Task first;
    first.target = opt_.placement * start;
    if (nc == 1) {
      first.node = *ch_.begin(root);
    } else {
      first.fork = true;
      first.node = root;
      first.group.assign(ch_.begin(root), ch_.end(root));
    }
    std::vector<Task> stack{first};
    while (!stack.empty()) {
      Task t = std::move(stack.back());
      stack.pop_back();
      if (t.fork) {
        fork(t, stack);
      } else {
        segment(t, stack);
      }
    }
    tree_.pose.clear();
    for (const Bone& b : tree_.bones) tree_.pose.push_back(b.rest);
    return std::move(tree_);
  }

 private:
  std::uint32_t pick_root() const {
    // The root with the most nodes below it (a scan may hold stray fragments).
    std::vector<std::uint32_t> size(sk_.size(), 1);
    for (std::size_t i = sk_.size(); i-- > 0;) {
      std::uint32_t p = sk_.nodes[i].parent;
      if (p != kNoParent && p < i) size[p] += size[i];
    }
    std::uint32_t best = kNone;
    for (std::uint32_t r : sk_.roots()) {
      if (best == kNone || size[r] > size[best]) best = r;
    }
    if (best == kNone) throw PiecesError("the skeleton is empty");
    return best;
  }

  double radius(std::uint32_t node) const {
    double r = sk_.nodes[node].radius * opt_.placement.s;
    return std::max(r, min_radius_);
  }
  double radius_at_fork(std::uint32_t node) const {
    double r = 0;
    for (const std::uint32_t* c = ch_.begin(node); c != ch_.end(node); ++c)
      r = std::max(r, radius(*c));
    return std::max(radius(node), r);
  }
  Vec3 world(const Vec3& p) const { return opt_.placement.point(p); }
  Vec3 direction(const Vec3& a, const Vec3& b, const Vec3& fallback) const {
    return normalized(opt_.placement.r.rotate(b - a), fallback);
  }
  Vec3 mean_direction(std::uint32_t node, const std::vector<std::uint32_t>& group,
                      const Vec3& fallback) const {
    Vec3 s{0, 0, 0};
    for (std::uint32_t c : group) {
      s += direction(sk_.nodes[node].position, sk_.nodes[c].position, fallback);
    }
    return normalized(s, fallback);
  }
  // The frame `from` turned by the shortest rotation taking its axis onto `dir`: no spurious roll
  // from one piece to the next.
  static Quat transport(const Quat& from, const Vec3& dir) {
    return (Quat::between(from.rotate(kAxis), dir) * from).normalized();
  }

  // Places a piece for task `t`: as the root piece, or hanging from t.parent/t.leaf. The
  // parent's terminal joint is set to t.target itself (so the parent's stem is aimed without
  // rolling about its axis) and the new piece's root rim is t.target turned by the twist: a
  // hexagon fits itself six ways, so the twist only turns the new piece (and its fork plane).
  std::uint32_t place(const Task& t, std::uint32_t type, int twist) {
    std::uint32_t pi;
    const Trs root_world = t.target * twist_rotation(twist);
    if (t.parent == kNone) {
      pi = place_piece(set_, tree_, type, kNone, 0, 0, root_world, opt_.tiles, opt_.seed);
    } else {
      pi = place_piece(set_, tree_, type, t.parent, t.leaf, twist, {}, opt_.tiles, opt_.seed);
      const PlacedPiece& pp = tree_.pieces[t.parent];
      std::uint32_t terminal = pp.bone_offset + set_.types[pp.type].leaves[t.leaf].joint;
      tree_.bones[terminal].rest = world_[pp.bone_offset].inverse() * t.target;
      world_[terminal] = t.target;
    }
    world_.push_back(root_world);
    // World frames of the new piece's terminal joints before fitting (their bind pose).
    const PieceType& pt = set_.types[type];
    for (std::size_t j = 1; j < pt.joints.size(); ++j) {
      world_.push_back(root_world * pt.joints[j].bind_local);
    }
    tree_.pieces[pi].topological = root_world.matrix();
    return pi;
  }

  int seeded_twist() const {
    return int(Rng::stream(opt_.seed, tree_.pieces.size(), 0x74776973).below(6));  // "twis"
  }
  const Trs& root_world(std::uint32_t pi) const { return world_[tree_.pieces[pi].bone_offset]; }

  void segment(const Task& t, std::vector<Task>& stack) {
    std::uint32_t pi = place(t, tube_, seeded_twist());
    const Trs root = root_world(pi);
    const Vec3 end = world(sk_.nodes[t.node].position);
    const Vec3 axis = root.r.rotate(kAxis);
    std::uint32_t n = ch_.count(t.node);
    Task next;
    next.parent = pi;
    next.leaf = 0;
    Vec3 dir = axis;
    double r = radius(t.node);
    if (n == 1) {
      std::uint32_t c = *ch_.begin(t.node);
      dir = direction(sk_.nodes[t.node].position, sk_.nodes[c].position, axis);
      r = radius(c);
      next.node = c;
    } else if (n >= 2) {
      next.fork = true;
      next.node = t.node;
      next.group.assign(ch_.begin(t.node), ch_.end(t.node));
      dir = mean_direction(t.node, next.group, axis);
      r = radius_at_fork(t.node);
    } else {
      r = radius(t.node) * 0.8;  // a tip: the open rim narrows a little more
    }
    // From the top rim's rest frame (the tube's top has no roll), turned onto the next segment.
    next.target = Trs{end, transport((root * set_.types[tube_].leaves[0].building).r, dir), r};
    if (n == 0) {
      set_terminal(pi, 0, next.target);
    } else {
      stack.push_back(std::move(next));
    }
  }

  // Sets a terminal joint of a placed piece so that its rim has world frame `target` (used for
  // open rims, which no child places).
  void set_terminal(std::uint32_t pi, std::uint32_t leaf, const Trs& target) {
    const PlacedPiece& p = tree_.pieces[pi];
    std::uint32_t terminal = p.bone_offset + set_.types[p.type].leaves[leaf].joint;
    tree_.bones[terminal].rest = world_[p.bone_offset].inverse() * target;
    world_[terminal] = target;
  }

  void fork(const Task& t, std::vector<Task>& stack) {
    const std::vector<std::uint32_t>& g = t.group;
    std::uint32_t type = fork_;
    std::vector<std::vector<std::uint32_t>> groups;
    if (g.size() == 3 && psi_ != kNone) {
      type = psi_;
      groups = {{g[0]}, {g[1]}, {g[2]}};
    } else {
      groups = {{g[0]}, std::vector<std::uint32_t>(g.begin() + 1, g.end())};
    }
    const PieceType& pt = set_.types[type];
    const Vec3 axis = t.target.r.rotate(kAxis);
    std::vector<Vec3> want(groups.size());
    for (std::size_t k = 0; k < groups.size(); ++k) {
      want[k] = mean_direction(t.node, groups[k], axis);
    }
    // The twist (one of six) and the assignment of groups to leaf rims (n! <= 6 orders) that
    // turn the rims least from where the unfitted piece has them.
    int best_twist = 0;
    std::vector<std::size_t> best;
    double best_cost = 1e300;
    for (int tw = 0; tw < 6; ++tw) {
      Trs root = t.target * twist_rotation(tw);
      std::vector<Vec3> have(pt.leaves.size());
      for (std::size_t l = 0; l < pt.leaves.size(); ++l) {
        have[l] = (root * pt.leaves[l].building).r.rotate(kAxis);
      }
      std::vector<std::size_t> order(pt.leaves.size());
      std::iota(order.begin(), order.end(), 0);
      do {
        double cost = 0;
        for (std::size_t k = 0; k < groups.size(); ++k) cost += 1 - dot(want[k], have[order[k]]);
        if (cost < best_cost - 1e-12) {
          best_cost = cost;
          best = order;
          best_twist = tw;
        }
      } while (std::next_permutation(order.begin(), order.end()));
    }
    std::uint32_t pi = place(t, type, best_twist);
    const Trs root = root_world(pi);
    const Vec3 origin = root.t;
    for (std::size_t k = 0; k < groups.size(); ++k) {
      std::uint32_t leaf = std::uint32_t(best[k]);
      // How far the leaf rim sits from the root rim in the unfitted piece, at this scale; never
      // more than 45% of the way to the nearest node it serves.
      double reach = length(pt.leaves[leaf].building.t) * root.s;
      for (std::uint32_t c : groups[k]) {
        Vec3 to = world(sk_.nodes[c].position);
        reach = std::min(reach, 0.45 * length(to - origin));
      }
      reach = std::max(reach, 1e-9);
      Task next;
      next.parent = pi;
      next.leaf = leaf;
      Vec3 dir = want[k];
      const Quat frame = transport((root * pt.leaves[leaf].building).r, dir);
      if (groups[k].size() == 1) {
        next.node = groups[k][0];
        next.target = Trs{origin + dir * reach, frame, radius(next.node)};
      } else {
        next.fork = true;
        next.node = t.node;
        next.group = groups[k];
        // A chained fork starts a little way along its children's mean direction.
        next.target = Trs{origin + dir * (0.5 * reach), frame, radius_at_fork(t.node)};
      }
      stack.push_back(std::move(next));
    }
    // Leaf rims no group uses (a Psi always has three groups, a Y two) stay as built.
  }

  const PieceSet& set_;
  const Skeleton& sk_;
  const FitOptions& opt_;
  Skeleton::Children ch_;
  std::uint32_t tube_ = kNone, fork_ = kNone, psi_ = kNone;
  double min_radius_ = 1e-6;
  Tree tree_;
  std::vector<Trs> world_;  // world frame of every bone so far (all similarities)
};

}  // namespace

Tree fit_skeleton(const PieceSet& set, const Skeleton& skeleton, const FitOptions& options) {
  if (std::string err = skeleton.validate(); !err.empty()) {
    throw PiecesError("the skeleton is not valid: " + err);
  }
  return Fitter(set, skeleton, options).run();
}

}  // namespace ramus::pieces
