#include "infer/skeleton/tropism_fit.h"

#include <algorithm>
#include <cmath>

namespace ramus::skeleton_infer {

namespace {

const Vec3 kDown{0, 0, -1};

// beta: the angle between a unit direction and T = down (radians, [0, pi]).
double angle_to_down(const Vec3& d) { return std::acos(std::clamp(-d.z, -1.0, 1.0)); }

struct Sums {
  double xy = 0, xx = 0, y = 0, yy = 0;
  std::size_t n = 0;
  void add(double x, double v) {
    xy += x * v, xx += x * x, y += v, yy += v * v;
    ++n;
  }
  ElasticityFit fit() const {
    ElasticityFit f;
    f.pairs = n;
    if (n < 3 || xx < 1e-12) return f;
    f.elasticity = xy / xx;
    // Residual sum of squares of the line through the origin, against the spread of y.
    const double rss = yy - 2 * f.elasticity * xy + f.elasticity * f.elasticity * xx;
    const double tss = yy - y * y / double(n);
    f.r2 = tss > 1e-15 ? std::clamp(1 - rss / tss, -1.0, 1.0) : 0.0;
    return f;
  }
};

}  // namespace

ElasticityFit fit_elasticity(const BranchRules& rules, int segments,
                             std::vector<ElasticityFit>* by_order) {
  Sums all;
  std::vector<Sums> per;
  const double n = double(std::max(segments, 1));
  for (const Internode& in : rules.internodes) {
    if (!in.continuation || in.parent == kNone) continue;
    const Internode& par = rules.internodes[in.parent];
    if (par.chord <= 1e-12 || in.chord <= 1e-12) continue;
    const double b0 = angle_to_down(par.direction), b1 = angle_to_down(in.direction);
    const double x = n * std::sin(b0), y = b0 - b1;
    all.add(x, y);
    if (by_order != nullptr) {
      if (per.size() <= in.order) per.resize(std::size_t(in.order) + 1);
      per[in.order].add(x, y);
    }
  }
  if (by_order != nullptr) {
    by_order->clear();
    for (const Sums& s : per) by_order->push_back(s.fit());
  }
  return all.fit();
}

Vec3 bend_towards(Vec3 heading, const Vec3& tropism, double elasticity, int segments) {
  // The turtle's apply_tropism (compiler/turtle.cpp): Rodrigues' rotation about H x T.
  for (int s = 0; s < segments && elasticity != 0; ++s) {
    const Vec3 axis = cross(heading, tropism);
    const double len = length(axis);
    if (len < 1e-12) break;
    const Vec3 k = axis / len;
    const double a = elasticity * len, c = std::cos(a), sn = std::sin(a);
    heading = normalized(heading * c + cross(k, heading) * sn + k * (dot(k, heading) * (1 - c)));
  }
  return heading;
}

void measure_from_bent_heading(BranchRules& rules, double elasticity, int segments) {
  if (elasticity == 0) return;
  for (NodeRule& r : rules.rules) {
    if (r.child_count == 0) continue;
    const Internode& par = rules.internodes[r.internode];
    const Vec3 bent = bend_towards(par.direction, kDown, elasticity, segments);
    ChildRule* b = rules.children.data() + r.child_begin;
    ChildRule* e = b + r.child_count;
    for (ChildRule* c = b; c != e; ++c) {
      angle_and_azimuth(bent, rules.internodes[c->internode].direction, c->theta, c->phi);
    }
    // Continuation first, then the laterals by increasing azimuth (as extracted).
    std::sort(b, e, [&](const ChildRule& x, const ChildRule& y) {
      const bool cx = rules.internodes[x.internode].continuation;
      const bool cy = rules.internodes[y.internode].continuation;
      if (cx != cy) return cx;
      if (x.phi != y.phi) return x.phi < y.phi;
      return x.internode < y.internode;
    });
  }
}

}  // namespace ramus::skeleton_infer
