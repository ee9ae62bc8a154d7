// d_avg of the inflation (reconstruct/bsg/sample_distance.h): the mean distance of the samples to
// their nearest edge, exact against a search over every edge, on the first call and on later
// calls after the BSG changed the ways a round of collapses changes it.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "core/rng.h"
#include "reconstruct/bsg/sample_distance.h"

using namespace ramus;
using namespace ramus::bsg;

namespace {

// One call of SampleDistances::mean.
double mean_sample_distance(const Bsg& bsg, const std::vector<Eigen::Vector3d>& samples,
                            const std::vector<std::uint32_t>& counts, double edge_sample) {
  SampleDistances distances(samples, edge_sample);
  return distances.mean(bsg, counts);
}

// A random tree: each node hangs from an earlier one, a step of about `step` away.
Bsg random_tree(Rng& rng, int n, double step) {
  Bsg b;
  b.pos.emplace_back(0, 0, 0);
  b.parent.push_back(kNone);
  for (int v = 1; v < n; ++v) {
    const std::uint32_t p = std::uint32_t(rng.below(std::uint64_t(v)));
    const Eigen::Vector3d d(rng.normal(0, 1), rng.normal(0, 1), rng.normal(0, 1) + 1);
    b.pos.push_back(b.pos[p] + step * rng.uniform(0.2, 2.0) * d.normalized());
    b.parent.push_back(p);
  }
  return b;
}

double brute_force_mean(const Bsg& b, const std::vector<Eigen::Vector3d>& samples,
                        const std::vector<std::uint32_t>& counts) {
  double sum = 0, weight = 0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    double best = std::numeric_limits<double>::infinity();
    for (std::uint32_t v = 1; v < b.size(); ++v)
      best = std::min(best, point_segment_distance(samples[i], b.pos[b.parent[v]], b.pos[v]));
    sum += counts[i] * best;
    weight += counts[i];
  }
  return sum / weight;
}

// Samples around the tree's nodes and edges, up to a few steps off.
std::vector<Eigen::Vector3d> samples_near(Rng& rng, const Bsg& b, int n, double step) {
  std::vector<Eigen::Vector3d> out;
  for (int i = 0; i < n; ++i) {
    const std::uint32_t v = 1 + std::uint32_t(rng.below(b.size() - 1));
    const Eigen::Vector3d on =
        b.pos[b.parent[v]] + rng.uniform01() * (b.pos[v] - b.pos[b.parent[v]]);
    out.push_back(on +
                  Eigen::Vector3d(rng.normal(0, step), rng.normal(0, step), rng.normal(0, step)));
  }
  return out;
}

}  // namespace

TEST_CASE("sample distances: the nearest edge of every sample, exactly", "[inflate]") {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    Rng rng(seed);
    const double step = rng.uniform(0.05, 0.5);
    const Bsg b = random_tree(rng, 2 + int(rng.below(300)), step);
    const std::vector<Eigen::Vector3d> samples = samples_near(rng, b, 400, step);
    std::vector<std::uint32_t> counts(samples.size());
    for (auto& c : counts) c = 1 + std::uint32_t(rng.below(5));
    // The along spacing sets the time only: a fine, the pipeline's and a coarse one agree.
    for (double spacing : {0.3 * step, step, 5 * step}) {
      INFO("seed " << seed << ", spacing " << spacing);
      CHECK(mean_sample_distance(b, samples, counts, spacing) ==
            Approx(brute_force_mean(b, samples, counts)).epsilon(1e-12));
    }
  }
}

TEST_CASE("sample distances: later calls after collapses, moves and pruning", "[inflate]") {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    INFO("seed " << seed);
    Rng rng(100 + seed);
    const double step = 0.2;
    Bsg b = random_tree(rng, 50 + int(rng.below(250)), step);
    const std::vector<Eigen::Vector3d> samples = samples_near(rng, b, 500, step);
    const std::vector<std::uint32_t> counts(samples.size(), 1);
    SampleDistances distances(samples, step);
    CHECK(distances.mean(b, counts) == Approx(brute_force_mean(b, samples, counts)).epsilon(1e-12));
    for (int round = 0; round < 6; ++round) {
      // A round's changes: some nodes merge into their parent (their children move up), some
      // move, leaves are pruned; the survivors are renumbered parents first.
      std::vector<std::uint32_t> parent = b.parent;
      std::vector<std::uint8_t> alive(b.size(), 1);
      for (std::uint32_t v = 1; v < b.size(); ++v) {
        const double u = rng.uniform01();
        if (u < 0.1) {
          alive[v] = 0;
        } else if (u < 0.15) {
          b.pos[v] += Eigen::Vector3d(rng.normal(0, 0.05), rng.normal(0, 0.05), 0);
        }
      }
      std::vector<std::uint32_t> keep, renumber(b.size(), kNone);
      for (std::uint32_t v = 0; v < b.size(); ++v) {
        if (!alive[v]) continue;
        std::uint32_t p = parent[v];
        while (p != kNone && !alive[p]) p = parent[p];
        renumber[v] = std::uint32_t(keep.size());
        keep.push_back(v);
        parent[v] = p;
      }
      Bsg next;
      for (std::uint32_t v : keep) {
        next.pos.push_back(b.pos[v]);
        next.parent.push_back(parent[v] == kNone ? kNone : renumber[parent[v]]);
      }
      b = next;
      if (b.size() < 2) break;
      INFO("round " << round << ", " << b.size() << " nodes");
      CHECK(distances.mean(b, counts) ==
            Approx(brute_force_mean(b, samples, counts)).epsilon(1e-12));
    }
  }
}

TEST_CASE("sample distances: edges of more than 1000 spacings, no edge, no sample", "[inflate]") {
  Bsg b;
  b.pos = {{0, 0, 0}, {0, 0, 50}, {30, 0, 50}};
  b.parent = {kNone, 0, 1};
  const std::vector<Eigen::Vector3d> samples = {{1, 0, 25}, {15, 2, 50}, {0.5, 0, 50.5}};
  const std::vector<std::uint32_t> counts = {1, 2, 1};
  // 0.01 m along points would be 5000 on the first edge: 1000 are laid, 5 cm apart.
  CHECK(mean_sample_distance(b, samples, counts, 0.01) ==
        Approx((1.0 + 2 * 2.0 + 0.5) / 4).epsilon(1e-12));
  Bsg single;
  single.pos = {{0, 0, 0}};
  single.parent = {kNone};
  CHECK(mean_sample_distance(single, samples, counts, 0.01) == 0.0);
  CHECK(mean_sample_distance(b, {}, {}, 0.01) == 0.0);
}
