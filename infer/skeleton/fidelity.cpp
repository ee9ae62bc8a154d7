#include "infer/skeleton/fidelity.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "infer/skeleton/branch_rules.h"

namespace ramus::skeleton_infer {

double ks_distance(std::vector<double> a, std::vector<double> b) {
  if (a.empty() && b.empty()) return 0;
  if (a.empty() || b.empty()) return 1;
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  const double na = double(a.size()), nb = double(b.size());
  std::size_t i = 0, j = 0;
  double d = 0;
  while (i < a.size() && j < b.size()) {
    // Step both empirical functions past the smallest remaining value, then compare them.
    const double x = std::min(a[i], b[j]);
    while (i < a.size() && a[i] == x) ++i;
    while (j < b.size() && b[j] == x) ++j;
    d = std::max(d, std::abs(double(i) / na - double(j) / nb));
  }
  return d;
}

const char* measure_name(Measure m) {
  switch (m) {
    case Measure::BranchLength:
      return "branch length";
    case Measure::BranchingAngle:
      return "branching angle";
    case Measure::Azimuth:
      return "azimuth";
    case Measure::RadiusRatio:
      return "radius ratio";
    case Measure::BranchOrder:
      return "branch order";
    case Measure::TotalLength:
      return "total length";
    case Measure::CrownExtent:
      return "crown extent";
    case Measure::Height:
      return "height";
  }
  return "?";
}

double to_resolution(double v) {
  if (!std::isfinite(v) || v == 0) return v;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*g", kMeasureDigits, v);  // correctly rounded
  return std::strtod(buf, nullptr);
}

void measure(const Skeleton& skeleton, Distributions& into) {
  const BranchRules rules = extract_branch_rules(skeleton);
  for (const Internode& in : rules.internodes) {
    into[Measure::BranchLength].push_back(to_resolution(in.length));
    into[Measure::BranchOrder].push_back(double(in.order));
  }
  for (const ChildRule& c : rules.children) {
    into[Measure::BranchingAngle].push_back(to_resolution(c.theta));
    into[Measure::Azimuth].push_back(to_resolution(c.phi));
    into[Measure::RadiusRatio].push_back(to_resolution(c.b));
  }
  // Per-tree measures: nodes of tree t are the start and end nodes of its internodes.
  const double inf = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < rules.tree_first.size(); ++t) {
    Vec3 lo{inf, inf, inf}, hi{-inf, -inf, -inf};
    const std::uint32_t tree = rules.internodes[rules.tree_first[t]].tree;
    for (std::uint32_t i = rules.tree_first[t];
         i < rules.internodes.size() && rules.internodes[i].tree == tree; ++i) {
      for (std::uint32_t n : {rules.internodes[i].start, rules.internodes[i].end}) {
        const Vec3& p = skeleton.nodes[n].position;
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
      }
    }
    into[Measure::TotalLength].push_back(to_resolution(rules.tree_length[t]));
    into[Measure::CrownExtent].push_back(to_resolution(std::max(hi.x - lo.x, hi.y - lo.y)));
    into[Measure::Height].push_back(to_resolution(hi.z - lo.z));
    ++into.trees;
  }
}

std::vector<MeasureComparison> compare(const Distributions& a, const Distributions& b) {
  std::vector<MeasureComparison> out;
  auto mean = [](const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return v.empty() ? 0.0 : s / double(v.size());
  };
  for (std::size_t m = 0; m < kMeasureCount; ++m) {
    MeasureComparison c;
    c.measure = Measure(m);
    c.count_a = a.samples[m].size();
    c.count_b = b.samples[m].size();
    c.mean_a = mean(a.samples[m]);
    c.mean_b = mean(b.samples[m]);
    c.ks = ks_distance(a.samples[m], b.samples[m]);
    out.push_back(c);
  }
  return out;
}

}  // namespace ramus::skeleton_infer
