// The stages of the reconstruction one by one, on graphs small enough to check by hand.
#include <catch2/catch.hpp>
#include <cmath>

#include "reconstruct/bsg/forest.h"
#include "reconstruct/bsg/graph.h"
#include "reconstruct/bsg/inflate.h"
#include "reconstruct/bsg/refine.h"

using namespace ramus::bsg;

namespace {

// A chain 0-1-...-(n-1) along `dir` with unit spacing.
Bsg chain(int n, Eigen::Vector3d dir) {
  Bsg b;
  for (int i = 0; i < n; ++i) {
    b.pos.push_back(double(i) * dir);
    b.parent.push_back(i == 0 ? kNone : std::uint32_t(i - 1));
    b.vertex.push_back(std::uint32_t(i));
    b.mass.push_back(1);
  }
  b.weight.assign(n, 0);
  b.radius.assign(n, 0);
  return b;
}

}  // namespace

TEST_CASE("reconstruct stages: importance weights are subtree edge-length sums", "[reconstruct]") {
  Bsg b = chain(4, Eigen::Vector3d::UnitZ());
  // A side twig of length 2 on vertex 1.
  b.pos.push_back(b.pos[1] + Eigen::Vector3d(2, 0, 0));
  b.parent.push_back(1);
  b.vertex.push_back(4);
  b.mass.push_back(1);
  importance_weights(b, 0.0);
  // Root: 3 (chain) + 2 (twig) = 5; normalized to 1.
  CHECK(b.weight[0] == Approx(1.0));
  CHECK(b.weight[1] == Approx(4.0 / 5.0));  // edges above 1: 2 + twig 2
  CHECK(b.weight[2] == Approx(1.0 / 5.0));
  CHECK(b.weight[3] == Approx(0.0));
  CHECK(b.weight[4] == Approx(0.0));
}

TEST_CASE("reconstruct stages: the orientation field of a straight chain is its direction",
          "[reconstruct]") {
  const Eigen::Vector3d dir = Eigen::Vector3d(1, 2, 2).normalized();
  Bsg b = chain(6, dir);
  importance_weights(b, 0.1);
  for (const auto& o : orientation_field(b)) CHECK(o.dot(dir) == Approx(1.0).epsilon(1e-9));
}

TEST_CASE("reconstruct stages: smoothing straightens a zig-zag and keeps its centre",
          "[reconstruct]") {
  Bsg b = chain(9, Eigen::Vector3d::UnitZ());
  for (std::size_t i = 1; i < b.size(); i += 2) b.pos[i].x() += 0.2;  // zig-zag
  Eigen::Vector3d before = Eigen::Vector3d::Zero();
  for (const auto& p : b.pos) before += p;
  // Zig-zag amplitude: how far each inner vertex is from the midpoint of its neighbours.
  auto spread = [](const Bsg& g) {
    double s = 0;
    for (std::size_t i = 1; i + 1 < g.size(); ++i) {
      s += (g.pos[i] - 0.5 * (g.pos[i - 1] + g.pos[i + 1])).norm();
    }
    return s / double(g.size() - 2);
  };
  const double zig = spread(b);
  refine(b, 0.1);
  Eigen::Vector3d after = Eigen::Vector3d::Zero();
  for (const auto& p : b.pos) after += p;
  CHECK(spread(b) < 0.5 * zig);
  CHECK((after - before).norm() / double(b.size()) < 0.1);
}

TEST_CASE("reconstruct stages: radii follow the allometric ratio and the mean distance",
          "[reconstruct]") {
  Bsg b = chain(5, Eigen::Vector3d::UnitZ());
  importance_weights(b, 0.5);
  assign_radii(b, 0.1, 2.5);
  for (std::size_t v = 1; v < b.size(); ++v) {
    // Eq. 5 read as r^2.5 proportional to c.
    const double ratio = std::pow(b.radius[v - 1] / b.radius[v], 2.5);
    CHECK(ratio == Approx(b.weight[v - 1] / b.weight[v]));
  }
  double cr = 0, c = 0;
  for (std::size_t v = 0; v < b.size(); ++v) cr += b.weight[v] * b.radius[v], c += b.weight[v];
  CHECK(cr / c == Approx(0.1));  // Eq. 7
  assign_radii(b, 0.1, 2.5, 0.3);
  CHECK(b.radius[0] == Approx(0.3));
}

TEST_CASE("reconstruct stages: a short twig inside the trunk's cylinder collapses",
          "[reconstruct]") {
  Bsg b = chain(4, Eigen::Vector3d::UnitZ());
  b.pos.push_back(b.pos[1] + Eigen::Vector3d(0.05, 0, 0.02));  // spurious twig on vertex 1
  b.parent.push_back(1);
  b.vertex.push_back(4);
  b.mass.push_back(1);
  importance_weights(b, 0.1);
  b.radius.assign(b.size(), 0.3);
  CHECK(collapse_overlaps(b, 0.5, 0.0) >= 1);
  CHECK(b.size() < 5);
  CHECK(b.parent[0] == kNone);
}

TEST_CASE("reconstruct stages: Dijkstra from two roots splits a line between them",
          "[reconstruct]") {
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i < 10; ++i) pts.emplace_back(0.1 * i, 0, 0);
  std::vector<std::uint32_t> point_vertex;
  Graph g = voxelize(pts, std::vector<std::uint8_t>(pts.size(), 1), 0.05, point_vertex);
  REQUIRE(g.size() == 10);
  link_nearest(g, 2);
  const std::vector<std::uint32_t> roots = {point_vertex[0], point_vertex[9]};
  const Forest f = shortest_path_forest(g, roots);
  for (int i = 0; i < 10; ++i) CHECK(f.tree[point_vertex[i]] == (i < 5 ? 0u : 1u));
  const Bsg t0 = extract_tree(g, f, 0, roots);
  CHECK(t0.size() == 5);
  for (std::size_t v = 1; v < t0.size(); ++v) CHECK(t0.parent[v] < v);
}

// A fork whose parent edge is in line with its lighter child: each edge removal moves the fork
// to the weighted midpoint, the parent's cylinder stretches with it and covers the next edge of
// that child, so without a bound the fork walks along it, and the heavier branch ends up hanging
// from far out on the lighter one (the weeping example's first limb, 0.55 m).
TEST_CASE("reconstruct stages: edge removal does not walk a fork along its lighter child",
          "[reconstruct]") {
  Bsg b = chain(2, Eigen::Vector3d(0.5, 0, 0));  // the stem, the fork u = 1 at x = 0.5
  const std::uint32_t u = 1;
  auto add = [&](const Eigen::Vector3d& p, std::uint32_t parent, double mass) {
    b.pos.push_back(p);
    b.parent.push_back(parent);
    b.vertex.push_back(std::uint32_t(b.vertex.size()));
    b.mass.push_back(mass);
    return std::uint32_t(b.pos.size() - 1);
  };
  // The lighter child: on along the stem's line in steps of 0.1, heavy with points.
  for (std::uint32_t k = 1, p = u; k <= 8; ++k) p = add({0.5 + 0.1 * k, 0, 0}, p, 20);
  // The heavier branch: up at 45 degrees, twice as long.
  for (std::uint32_t k = 1, p = u; k <= 12; ++k) p = add({0.5 + 0.1 * k, 0, 0.1 * k}, p, 1);
  importance_weights(b, 0.0);
  b.radius.assign(b.size(), 0.15);
  const Eigen::Vector3d fork = b.pos[u];
  for (int round = 0; round < 40 && collapse_overlaps(b, 0.5, 0.0) > 0; ++round) {
  }
  // The fork is the node with two children; it stays within a tenth of its radius (unbounded,
  // it went 0.25 m along the lighter child).
  std::vector<int> children(b.size(), 0);
  for (std::size_t v = 1; v < b.size(); ++v) ++children[b.parent[v]];
  std::size_t forks = 0;
  for (std::size_t v = 0; v < b.size(); ++v) {
    if (children[v] < 2) continue;
    ++forks;
    INFO("fork at " << b.pos[v].transpose());
    CHECK((b.pos[v] - fork).norm() <= 0.1 * 0.15 + 1e-12);
  }
  CHECK(forks == 1);
}
