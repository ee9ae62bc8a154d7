#include "infer/skeleton/species_params.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ramus::skeleton_infer {

namespace {

// Fewer fine internodes than this and the whole tree is measured instead (a scaffold that took
// almost everything, a sparse scan).
constexpr std::size_t kMinSamples = 8;

constexpr double kMinLateralShare = 0.05, kMaxLateralShare = 0.45;

double median_or(std::vector<double> v, double fallback) {
  if (v.empty()) return fallback;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

double quantile_or(std::vector<double> v, double q, double fallback) {
  if (v.empty()) return fallback;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, std::size_t(q * double(v.size() - 1) + 0.5))];
}

void mean_sd(const std::vector<double>& v, double& mean, double& sd) {
  if (v.empty()) return;
  double sum = 0;
  for (double x : v) sum += x;
  mean = sum / double(v.size());
  double var = 0;
  for (double x : v) var += (x - mean) * (x - mean);
  sd = v.size() > 1 ? std::sqrt(var / double(v.size() - 1)) : 0.0;
}

double chord_of(const Internode& in) { return std::max(in.chord, 1e-6); }

}  // namespace

SpeciesParams fit_species_params(const BranchRules& rules, const Scaffold& scaffold,
                                 double height) {
  SpeciesParams p;
  const std::uint32_t tree_id = rules.internodes[rules.tree_first[scaffold.tree]].tree;
  std::vector<std::uint32_t> fine, all;
  for (std::uint32_t i = 0; i < rules.internodes.size(); ++i) {
    if (rules.internodes[i].tree != tree_id) continue;
    all.push_back(i);
    if (!scaffold.in_scaffold[i]) fine.push_back(i);
  }
  const std::vector<std::uint32_t>& used = fine.size() >= kMinSamples ? fine : all;

  std::vector<double> branch, kink, cont_width, lat_width, share, chords, lat_side, kink_side;
  std::size_t going = 0, one = 0, two = 0;
  for (std::uint32_t i : used) {
    const Internode& in = rules.internodes[i];
    chords.push_back(chord_of(in));
    const NodeRule& r = rules.rules[i];
    const std::uint32_t cont = scaffold.continuation[i];
    std::size_t laterals = 0;
    for (const ChildRule* c = rules.begin(r); c != rules.end(r); ++c) {
      if (c->internode == cont) {
        kink.push_back(c->theta);
        kink_side.push_back(std::abs(c->phi - 180));
        cont_width.push_back(c->b);
      } else {
        ++laterals;
        branch.push_back(c->theta);
        lat_side.push_back(std::abs(c->phi - 180));
        lat_width.push_back(c->b);
        // Of what the shoot carries past this internode, the share its lateral carries.
        if (cont != kNone && scaffold.carried[c->internode] + scaffold.carried[cont] > 0)
          share.push_back(scaffold.carried[c->internode] /
                          (scaffold.carried[c->internode] + scaffold.carried[cont]));
      }
    }
    if (cont != kNone) {
      ++going;
      one += laterals == 1 ? 1 : 0;
      two += laterals >= 2 ? 1 : 0;
    }
  }
  mean_sd(branch, p.branch_angle, p.branch_angle_sd);
  mean_sd(kink, p.kink_angle, p.kink_angle_sd);
  mean_sd(lat_side, p.lateral_side, p.lateral_side_sd);
  mean_sd(kink_side, p.kink_side, p.kink_side_sd);
  // Widths never grow from parent to child (a reconstruction's radii can).
  p.continuation_width = std::clamp(median_or(cont_width, 0.9), 0.3, 1.0);
  p.lateral_width = std::clamp(median_or(lat_width, 0.6), 0.1, 1.0);
  // Below a half, so that two laterals leave their shoot something to go on with.
  p.lateral_share = std::clamp(median_or(share, 0.3), kMinLateralShare, kMaxLateralShare);
  if (going > 0) {
    p.p_one = double(one) / double(going);
    p.p_two = double(two) / double(going);
  }
  p.max_internode = std::min(quantile_or(chords, 0.95, height / 5), height / 5);
  p.min_internode = std::min(quantile_or(chords, 0.05, p.max_internode / 10), p.max_internode);
  // Each internode's length is drawn on its own: the ratios of successive internodes of a
  // reconstruction are dominated by noise and tips, and a median ratio compounded along a shoot
  // runs its internodes to one end of the range (too few laterals, half the input's length).
  mean_sd(chords, p.internode_length, p.internode_length_sd);
  p.internode_length = std::clamp(p.internode_length, p.min_internode, p.max_internode);

  // Derivation steps: the longest chain of internodes from a scaffold internode to a fine tip.
  for (std::uint32_t i : fine) {
    int steps = 0;
    for (std::uint32_t k = i; k != kNone && !scaffold.in_scaffold[k];
         k = rules.internodes[k].parent)
      ++steps;
    p.depth = std::max(p.depth, steps);
  }
  return p;
}

}  // namespace ramus::skeleton_infer
