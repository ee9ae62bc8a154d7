// Euclidean minimum spanning trees (infer/wavelet/emst.h; III-E).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>

#include "infer/wavelet/emst.h"
#include "wavelet_test_util.h"

using namespace ramus;
using namespace ramus::wavelet;

namespace {

// Prim's algorithm on the complete graph, O(n^2): the paper's method, as an in-process oracle.
double prim_weight(const std::vector<Vec3>& p) {
  const std::size_t n = p.size();
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<char> in(n, 0);
  double total = 0;
  dist[0] = 0;
  for (std::size_t it = 0; it < n; ++it) {
    std::size_t u = n;
    for (std::size_t i = 0; i < n; ++i) {
      if (!in[i] && (u == n || dist[i] < dist[u])) u = i;
    }
    in[u] = 1;
    total += dist[u];
    for (std::size_t v = 0; v < n; ++v) {
      if (!in[v]) dist[v] = std::min(dist[v], distance(p[u], p[v]));
    }
  }
  return total;
}

std::vector<Vec3> random_points(std::size_t n, std::uint64_t seed, bool lattice) {
  Rng rng(seed);
  std::vector<Vec3> pts;
  for (std::size_t i = 0; i < n; ++i) {
    if (lattice) {
      pts.push_back(Vec3(double(rng.below(12)), double(rng.below(12)), double(rng.below(12))));
    } else {
      pts.push_back(Vec3(rng.uniform(0, 10), rng.uniform(0, 10), rng.uniform(0, 3)));
    }
  }
  return pts;
}

bool spans(std::size_t n, const std::vector<MstEdge>& edges) {
  std::vector<std::uint32_t> parent(n);
  for (std::uint32_t i = 0; i < n; ++i) parent[i] = i;
  auto find = [&](std::uint32_t x) {
    while (parent[x] != x) x = parent[x];
    return x;
  };
  for (const MstEdge& e : edges) parent[find(e.a)] = find(e.b);
  for (std::uint32_t i = 0; i < n; ++i) {
    if (find(i) != find(0)) return false;
  }
  return edges.size() + 1 == n;
}

}  // namespace

TEST_CASE("emst: equals Prim on the complete graph also with many ties", "[wavelet]") {
  for (bool lattice : {false, true}) {
    for (std::size_t n : {2u, 3u, 17u, 300u, 1500u}) {
      std::vector<Vec3> pts = random_points(n, 40 + n, lattice);
      std::vector<MstEdge> e = euclidean_mst(pts);
      INFO("n = " << n << (lattice ? " on a lattice" : ""));
      CHECK(spans(n, e));
      CHECK(total_length(e) == Approx(prim_weight(pts)).epsilon(1e-12));
    }
  }
}

TEST_CASE("emst: trivial and bad inputs", "[wavelet]") {
  CHECK(euclidean_mst({}).empty());
  CHECK(euclidean_mst({Vec3{1, 2, 3}}).empty());
  std::vector<MstEdge> dup = euclidean_mst({Vec3{1, 1, 1}, Vec3{1, 1, 1}, Vec3{1, 1, 1}});
  CHECK(dup.size() == 2);
  CHECK(total_length(dup) == 0);
  CHECK_THROWS_AS(euclidean_mst({Vec3{0, 0, 0}, Vec3{std::nan(""), 0, 0}}), std::invalid_argument);
}

TEST_CASE("emst: total weight equals SciPy's minimum_spanning_tree", "[wavelet][oracle]") {
  std::string python = test::python_with("numpy, scipy.sparse.csgraph, scipy.spatial");
  if (python.empty()) {
    WARN(
        "skipped: no python3 with numpy and scipy (scripts/install-deps.sh installs "
        "python3-scipy)");
    return;
  }
  for (std::size_t n : {50u, 400u, 1200u}) {
    std::vector<Vec3> pts = random_points(n, 7 * n, false);
    std::string in = test::temp_path("mst_in.txt");
    {
      std::ofstream f(in);
      f.precision(17);
      for (const Vec3& p : pts) f << p.x << " " << p.y << " " << p.z << "\n";
    }
    std::string cmd = python + " " + test::tool("scipy_mst.py") + " " + in;
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
    REQUIRE(pipe);
    double scipy = -1;
    REQUIRE(std::fscanf(pipe.get(), "%lf", &scipy) == 1);
    INFO("n = " << n);
    CHECK(total_length(euclidean_mst(pts)) == Approx(scipy).epsilon(1e-10));
    std::remove(in.c_str());
  }
}
