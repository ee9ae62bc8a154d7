// make_wind_rig: joints along the longest, lowest-order branch chains (the trunk first), within
// a joint budget; every other chain rides on the joint where it leaves its parent.
#include "mesh/wind_rig.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "mesh/builders.h"

namespace ramus::mesh {
namespace {

// Peak angle per joint (radians). The angles add up along the hierarchy: a trunk of 4 joints
// leans its top by ~0.05 rad (2.9 degrees), a branch swings its tip by ~0.1 rad more.
constexpr double kTrunkAmplitude = 0.02;
constexpr double kBranchAmplitude = 0.04;

struct ChainArc {
  double length = 0;
  std::vector<double> fraction;  // arc fraction at each of the chain's nodes
};

ChainArc chain_arc(const Skeleton& s, const Chain& ch) {
  ChainArc a;
  a.fraction.assign(ch.nodes.size(), 0.0);
  for (std::size_t k = 1; k < ch.nodes.size(); ++k) {
    a.length += distance(s.nodes[ch.nodes[k]].position, s.nodes[ch.nodes[k - 1]].position);
    a.fraction[k] = a.length;
  }
  for (double& f : a.fraction) f = a.length > 0 ? f / a.length : 1.0;
  return a;
}

// Joints along a chain: the trunk bends in up to 6 places, a branch in up to 4, about one per
// sixth (trunk) or third (branch) of the tree's height.
int joints_along(double length, double height, bool trunk) {
  const double per = trunk ? 6.0 : 3.0;
  const int most = trunk ? 6 : 4;
  return std::clamp(int(std::ceil(per * length / height)), trunk ? 2 : 1, most);
}

// Where a node sits between the `count` joints of a chain starting at `first`: k = floor(f n),
// blending toward joint k+1 by the rest; past the last joint it follows that joint alone.
JointBinding bind(std::uint32_t first, int count, double fraction) {
  const double x = std::clamp(fraction, 0.0, 1.0) * count;
  const int k = std::min(int(x), count - 1);
  if (k + 1 >= count) return {first + std::uint32_t(k), first + std::uint32_t(k), 0.0f};
  return {first + std::uint32_t(k), first + std::uint32_t(k + 1), float(x - k)};
}

}  // namespace

double WindRig::angle(std::size_t j, double time) const {
  const WindJoint& w = joints[j];
  return w.amplitude * std::sin(2 * std::numbers::pi * (w.cycles * time / period + w.phase));
}

WindRig make_wind_rig(const Skeleton& s, const PreparedSkeleton& p, const WindField& wind,
                      const WindRigOptions& options) {
  WindRig rig;
  rig.period = options.period;
  rig.node_binding.assign(s.nodes.size(), JointBinding{});
  const std::size_t n = p.chains.size();
  const double height = std::max(p.hi.z - p.lo.z, std::max(p.extent, 1e-9) * 1e-3);
  std::vector<ChainArc> arcs;
  arcs.reserve(n);
  for (const Chain& ch : p.chains) arcs.push_back(chain_arc(s, ch));

  // Choose the chains that get joints: lowest order first, then longest; a chain only when its
  // parent has joints (so its base joint has one to hang from) and it is at least a tenth of
  // the tree's height.
  std::vector<std::uint32_t> by_rank(n);
  std::iota(by_rank.begin(), by_rank.end(), 0u);
  std::stable_sort(by_rank.begin(), by_rank.end(), [&](std::uint32_t a, std::uint32_t b) {
    if (p.chains[a].order != p.chains[b].order) return p.chains[a].order < p.chains[b].order;
    return arcs[a].length > arcs[b].length;
  });
  std::vector<int> count(n, 0);
  int budget = options.max_joints;
  for (std::uint32_t c : by_rank) {
    const Chain& ch = p.chains[c];
    const bool trunk = ch.parent_chain == kNoChain;
    if (!trunk && (count[ch.parent_chain] == 0 || arcs[c].length < 0.1 * height)) continue;
    const int j = joints_along(arcs[c].length, height, trunk);
    if (j > budget) continue;
    count[c] = j;
    budget -= j;
  }

  // Joints and bindings, chains in their order (parents first).
  for (std::uint32_t c = 0; c < n; ++c) {
    const Chain& ch = p.chains[c];
    const bool trunk = ch.parent_chain == kNoChain;
    if (count[c] == 0) {
      // No joints: the chain moves with the node it starts from (for a trunk without joints,
      // the fixed joint 0, the default binding).
      const JointBinding at = trunk ? JointBinding{} : rig.node_binding[ch.nodes.front()];
      for (std::size_t k = trunk ? 0 : 1; k < ch.nodes.size(); ++k)
        rig.node_binding[ch.nodes[k]] = at;
      continue;
    }
    const std::uint32_t first = std::uint32_t(rig.joints.size());
    const Vec3 start = s.nodes[ch.nodes.front()].position;
    const Vec3 end = s.nodes[ch.nodes.back()].position;
    Vec3 axis{0, 1, 0};  // the trunk bends along +x, the wind's direction
    if (!trunk) axis = normalized(cross(end - start, Vec3{0, 0, 1}), axis);
    for (int k = 0; k < count[c]; ++k) {
      WindJoint j;
      // The joint sits on the chain at arc fraction k / count.
      const double f = double(k) / count[c];
      std::size_t seg = 1;
      while (seg + 1 < ch.nodes.size() && arcs[c].fraction[seg] < f) ++seg;
      const double f0 = arcs[c].fraction[seg - 1], f1 = arcs[c].fraction[seg];
      const double u = f1 > f0 ? std::clamp((f - f0) / (f1 - f0), 0.0, 1.0) : 0.0;
      const Vec3 a = s.nodes[ch.nodes[seg - 1]].position, b = s.nodes[ch.nodes[seg]].position;
      j.position = ch.nodes.size() > 1 ? a + (b - a) * u : start;
      j.axis = axis;
      if (k > 0) {
        j.parent = first + k - 1;
      } else if (!trunk) {
        const JointBinding at = rig.node_binding[ch.nodes.front()];
        j.parent = at.t < 0.5f ? at.a : at.b;
      }
      if (trunk) {
        j.amplitude = kTrunkAmplitude * k / count[c];  // k = 0, the base, stays fixed
      } else {
        j.amplitude = kBranchAmplitude * (k + 1) / count[c];
        j.phase = wind.chain_phase[c];
        j.cycles = 2;
      }
      rig.joints.push_back(j);
    }
    for (std::size_t k = trunk ? 0 : 1; k < ch.nodes.size(); ++k)
      rig.node_binding[ch.nodes[k]] = bind(first, count[c], arcs[c].fraction[k]);
  }
  return rig;
}

}  // namespace ramus::mesh
