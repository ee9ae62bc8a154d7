#include "infer/skeleton/branch_rules.h"

#include <algorithm>
#include <cmath>

namespace ramus::skeleton_infer {

namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;

struct PendingChain {
  std::uint32_t start;   // node the chain hangs from
  std::uint32_t first;   // its first node
  std::uint32_t parent;  // internode ending at start
  std::uint32_t tree;
};

}  // namespace

void levelled_frame(const Vec3& heading, Vec3& left, Vec3& up) {
  const Vec3 v{0, 0, 1};
  const Vec3 l = cross(v, heading);
  if (length(l) < 1e-9) {
    // `$` leaves a vertical frame as it is; the turtle starts with L = (-1, 0, 0).
    left = normalized(Vec3{-1, 0, 0} - heading * dot(Vec3{-1, 0, 0}, heading), Vec3{0, 1, 0});
  } else {
    left = normalized(l);
  }
  up = cross(heading, left);
}

// The turtle's `/(phi)` turns U into U cos(phi) + L sin(phi), and `&(theta)` turns H into
// H cos(theta) - U' sin(theta). So d = H cos(theta) - sin(theta) (U cos(phi) + L sin(phi)), and
// the part w of d perpendicular to H gives phi = atan2(-w.L, -w.U).
void angle_and_azimuth(const Vec3& parent, const Vec3& d, double& theta, double& phi) {
  Vec3 l, u;
  levelled_frame(parent, l, u);
  const double c = std::clamp(dot(parent, d), -1.0, 1.0);
  const Vec3 w = d - parent * c;
  theta = std::atan2(length(w), c) * kDeg;
  if (length(w) < 1e-12) {
    phi = 0;
    return;
  }
  phi = std::atan2(-dot(w, l), -dot(w, u)) * kDeg;
  if (phi < 0) phi += 360;
  if (phi >= 360) phi -= 360;
}

BranchRules extract_branch_rules(const Skeleton& skeleton) {
  if (std::string why = skeleton.validate(); !why.empty()) throw ExtractError(why);
  BranchRules out;
  const Skeleton::Children kids = skeleton.children();
  const std::vector<std::uint32_t> roots = skeleton.roots();
  const auto& nodes = skeleton.nodes;

  // Walks one chain through nodes with exactly one child.
  auto make_internode = [&](const PendingChain& p) {
    Internode in;
    in.start = p.start;
    in.parent = p.parent;
    in.tree = p.tree;
    in.radius = nodes[p.first].radius;
    std::uint32_t n = p.first;
    double len = distance(nodes[p.start].position, nodes[n].position);
    while (kids.count(n) == 1) {
      const std::uint32_t next = *kids.begin(n);
      len += distance(nodes[n].position, nodes[next].position);
      n = next;
    }
    in.end = n;
    in.length = len;
    const Vec3 chord = nodes[n].position - nodes[p.start].position;
    const double cl = length(chord);
    in.chord = cl;
    if (cl > 1e-12) {
      in.direction = chord / cl;
    } else if (p.parent != kNone) {
      in.direction = out.internodes[p.parent].direction;
    }
    return in;
  };

  std::vector<PendingChain> children_of;  // scratch: the chains starting at one node
  std::vector<std::uint32_t> stack;       // internodes whose end is still to be expanded
  out.internodes.reserve(nodes.size() / 2 + 1);
  for (std::uint32_t t = 0; t < roots.size(); ++t) {
    const std::uint32_t root = roots[t];
    if (kids.count(root) == 0) continue;
    const auto tree_first = std::uint32_t(out.internodes.size());
    // Every chain leaving the root starts an axis of order 0.
    for (const std::uint32_t* c = kids.begin(root); c != kids.end(root); ++c) {
      Internode in = make_internode({root, *c, kNone, t});
      in.continuation = false;
      out.internodes.push_back(in);
      stack.push_back(std::uint32_t(out.internodes.size() - 1));
    }
    while (!stack.empty()) {
      const std::uint32_t pi = stack.back();
      stack.pop_back();
      const std::uint32_t end = out.internodes[pi].end;
      if (kids.count(end) < 2) continue;
      const auto first = std::uint32_t(out.internodes.size());
      for (const std::uint32_t* c = kids.begin(end); c != kids.end(end); ++c) {
        out.internodes.push_back(make_internode({end, *c, pi, t}));
      }
      const auto last = std::uint32_t(out.internodes.size());
      // The child closest in direction continues the parent's axis (ties: the first child).
      const Vec3 pd = out.internodes[pi].direction;
      std::uint32_t cont = first;
      double best = -2;
      for (std::uint32_t i = first; i < last; ++i) {
        const double c = dot(pd, out.internodes[i].direction);
        if (c > best) best = c, cont = i;
      }
      for (std::uint32_t i = first; i < last; ++i) {
        Internode& in = out.internodes[i];
        const Internode& par = out.internodes[pi];
        in.depth = par.depth + 1;
        in.continuation = i == cont;
        in.order = in.continuation ? par.order : std::uint16_t(std::min(par.order + 1, 0xffff));
        in.axis_index = in.continuation ? par.axis_index + 1 : 0;
        stack.push_back(i);
      }
    }
    double total = 0;
    for (auto i = tree_first; i < out.internodes.size(); ++i) total += out.internodes[i].length;
    out.tree_first.push_back(tree_first);
    out.tree_length.push_back(total);
  }

  // Rules: one per internode, children at its end (Eq. 4.11).
  std::vector<std::uint32_t> child_count(out.internodes.size(), 0);
  for (const Internode& in : out.internodes) {
    if (in.parent != kNone) ++child_count[in.parent];
  }
  out.rules.resize(out.internodes.size());
  std::uint32_t offset = 0;
  for (std::uint32_t i = 0; i < out.internodes.size(); ++i) {
    out.rules[i].internode = i;
    out.rules[i].child_begin = offset;
    offset += child_count[i];
  }
  out.children.resize(offset);
  std::vector<std::uint32_t> fill(out.internodes.size(), 0);
  for (std::uint32_t i = 0; i < out.internodes.size(); ++i) {
    const Internode& in = out.internodes[i];
    if (in.parent == kNone) continue;
    const Internode& par = out.internodes[in.parent];
    ChildRule c;
    angle_and_azimuth(par.direction, in.direction, c.theta, c.phi);
    c.a = par.length > 0 ? in.length / par.length : 1.0;
    c.b = par.radius > 0 ? in.radius / par.radius : 1.0;
    c.internode = i;
    out.children[out.rules[in.parent].child_begin + fill[in.parent]++] = c;
  }
  for (NodeRule& r : out.rules) {
    ChildRule* b = out.children.data() + r.child_begin;
    r.child_count = fill[r.internode];
    ChildRule* e = b + r.child_count;
    std::sort(b, e, [&](const ChildRule& x, const ChildRule& y) {
      const bool cx = out.internodes[x.internode].continuation;
      const bool cy = out.internodes[y.internode].continuation;
      if (cx != cy) return cx;
      if (x.phi != y.phi) return x.phi < y.phi;
      return x.internode < y.internode;
    });
  }
  return out;
}

}  // namespace ramus::skeleton_infer
