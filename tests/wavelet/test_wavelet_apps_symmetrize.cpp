// Symmetrization about the scanner plane (Friedman & Stamos 2013, IV-D): the reflection is an
// involution whose plane holds the root, the merged cloud is symmetric, an already symmetric
// cloud is left as it was, and `ramus symmetrize` writes such a cloud for a real scan.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <string>

#include "../cli/cli_runner.h"
#include "core/rng.h"
#include "formats/point_cloud_io.h"
#include "infer/wavelet/alignment.h"
#include "infer/wavelet/symmetrize.h"

using namespace ramus;
using namespace ramus::wavelet;

namespace {

// A random alignment: root anywhere (large coordinates too), horizontal scanner direction.
Alignment random_alignment(Rng& rng) {
  Alignment a;
  a.root = {rng.uniform(-1e5, 1e5), rng.uniform(-1e5, 1e5), rng.uniform(-100, 100)};
  const double t = rng.uniform(0, 2 * M_PI);
  a.scanner_dir = {std::cos(t), std::sin(t), 0};
  a.angle = std::atan2(a.scanner_dir.x, a.scanner_dir.y);
  a.source = ScannerSource::given;
  return a;
}

// A cloud of `n` random points above a root at `root`, scanner at `scanner`; the root is the
// unique lowest point.
PointCloud random_cloud(Rng& rng, std::size_t n, const Vec3& root, const Vec3& scanner) {
  PointCloud c;
  c.offset = root;
  c.positions.push_back({0, 0, 0});
  for (std::size_t i = 1; i < n; ++i) {
    c.positions.push_back(Vec3f(Vec3{rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(0.1, 8)}));
  }
  c.scanner = scanner;
  return c;
}

double nearest_distance(const PointCloud& c, const Vec3& world) {
  double best = INFINITY;
  for (std::size_t i = 0; i < c.size(); ++i) best = std::min(best, distance(c.world(i), world));
  return best;
}

}  // namespace

TEST_CASE("symmetrize: the reflection is an involution and fixes the plane through the root",
          "[wavelet][symmetrize]") {
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    Rng rng(seed);
    const Alignment a = random_alignment(rng);
    const Vec3 p = a.root + Vec3{rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(0, 50)};
    const Vec3 q = reflect_about_scanner_plane(a, p);
    CHECK(distance(reflect_about_scanner_plane(a, q), p) < 1e-9 * (1 + length(p)));
    // The root and every point of the vertical plane through it across the scanner direction
    // stay where they are.
    CHECK(distance(reflect_about_scanner_plane(a, a.root), a.root) == 0);
    const Vec3 across{-a.scanner_dir.y, a.scanner_dir.x, 0};
    const Vec3 on_plane = a.root + across * rng.uniform(-20, 20) + Vec3{0, 0, rng.uniform(0, 20)};
    CHECK(distance(reflect_about_scanner_plane(a, on_plane), on_plane) < 1e-9 * length(on_plane));
    // In the aligned frame of III-A the plane is y = 0: x and z are kept, y changes sign.
    const Vec3 pa = a.to_aligned(p), qa = a.to_aligned(q);
    CHECK(qa.x == Approx(pa.x).margin(1e-6));
    CHECK(qa.y == Approx(-pa.y).margin(1e-6));
    CHECK(qa.z == Approx(pa.z).margin(1e-6));
    // A point is as far from the plane as its image, on the other side.
    CHECK(dot(q - a.root, a.scanner_dir) == Approx(-dot(p - a.root, a.scanner_dir)).margin(1e-6));
  }
}

TEST_CASE("symmetrize: the merged cloud is symmetric and aligns as the input did",
          "[wavelet][symmetrize]") {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    Rng rng(seed * 7919);
    const Vec3 root{rng.uniform(-1e3, 1e3), rng.uniform(-1e3, 1e3), rng.uniform(0, 10)};
    const Vec3 scanner = root + Vec3{rng.uniform(-30, 30), rng.uniform(-30, 30), 1.5};
    PointCloud cloud = random_cloud(rng, 300, root, scanner);
    cloud.normals.assign(cloud.size(), Vec3f{0.6f, 0.0f, 0.8f});
    cloud.intensity.assign(cloud.size(), 7.0f);
    const AlignedCloud aligned = align_cloud(cloud);
    const Symmetrized s = symmetrize(cloud, aligned.alignment);
    // Only the root lies on the plane; every other random point gets a distinct image.
    CHECK(s.merged == 1);
    CHECK(s.reflected == cloud.size() - 1);
    REQUIRE(s.cloud.size() == 2 * cloud.size() - 1);
    CHECK(s.cloud.normals.size() == s.cloud.size());
    CHECK(s.cloud.intensity.size() == s.cloud.size());
    for (std::size_t i = 0; i < cloud.size(); ++i)
      CHECK(s.cloud.positions[i] == cloud.positions[i]);
    for (std::size_t i = 0; i < s.cloud.size(); ++i) {
      const Vec3 image = reflect_about_scanner_plane(aligned.alignment, s.cloud.world(i));
      CHECK(nearest_distance(s.cloud, image) < 1e-4);
    }
    // A reflected normal is the mirror image of the input's.
    const Vec3 n = Vec3(s.cloud.normals.back());
    const Vec3 d = aligned.alignment.scanner_dir;
    CHECK(distance(n, Vec3{0.6, 0, 0.8} - 2.0 * dot(Vec3{0.6, 0, 0.8}, d) * d) < 1e-6);
    // The root stays the lowest point and the scanner is kept: the same alignment.
    const AlignedCloud again = align_cloud(s.cloud);
    CHECK(distance(again.alignment.root, aligned.alignment.root) == 0);
    CHECK(again.alignment.angle == aligned.alignment.angle);
  }
}

TEST_CASE("symmetrize: a cloud that is already symmetric stays the same set",
          "[wavelet][symmetrize]") {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    Rng rng(seed);
    const Alignment a = random_alignment(rng);
    PointCloud cloud;
    cloud.offset = a.root;
    cloud.scanner = a.root - a.scanner_dir * 25.0;
    cloud.positions.push_back({0, 0, 0});
    // Mirror pairs built in the aligned frame, (x, y, z) and (x, -y, z).
    for (int i = 0; i < 150; ++i) {
      const Vec3 p{rng.uniform(-3, 3), rng.uniform(0.05, 3), rng.uniform(0.1, 8)};
      for (double sign : {1.0, -1.0}) {
        const Vec3 w = a.to_world({p.x, sign * p.y, p.z});
        cloud.positions.push_back(Vec3f(w - cloud.offset));
      }
    }
    const AlignedCloud aligned = align_cloud(cloud);
    const Symmetrized s = symmetrize(cloud, aligned.alignment);
    CHECK(s.reflected == 0);
    CHECK(s.merged == cloud.size());
    CHECK(s.cloud.positions == cloud.positions);
  }
}

TEST_CASE("symmetrize: an explicit merge distance merges near images and zero merges none",
          "[wavelet][symmetrize]") {
  Rng rng(5);
  PointCloud cloud = random_cloud(rng, 200, {0, 0, 0}, {0, -20, 1});
  const Alignment a = align_cloud(cloud).alignment;
  SymmetrizeOptions none;
  none.merge_distance = 0;
  // The root is its own image at distance exactly 0, so it is merged even then.
  CHECK(symmetrize(cloud, a, none).merged == 1);
  SymmetrizeOptions wide;
  wide.merge_distance = 100;  // larger than the cloud: every image is near an input point
  CHECK(symmetrize(cloud, a, wide).cloud.size() == cloud.size());
}

TEST_CASE("symmetrize cli: a real scan, the scanner to reuse, and bad arguments",
          "[wavelet][symmetrize][cli]") {
  const std::string scan = std::string(RAMUS_SHARED_DIR) + "/data/rtwig_cloud.txt";
  if (!std::filesystem::exists(scan)) {
    WARN("skipped: " << scan << " is missing");
    return;
  }
  const std::string dir = std::string(RAMUS_BINARY_DIR) + "/wavelet_apps_symmetrize";
  std::filesystem::create_directories(dir);
  const cli_test::CliResult r =
      cli_test::run_ramus_shell("-q symmetrize " + scan + " -o " + dir + "/sym.ply");
  REQUIRE(r.status == 0);
  const PointCloud in = read_point_cloud(scan);
  const PointCloud out = read_point_cloud(dir + "/sym.ply");
  CHECK(out.size() > in.size());
  CHECK(out.size() <= 2 * in.size());
  CHECK(r.out.find(" = " + std::to_string(out.size())) != std::string::npos);
  // The printed --scanner aligns the output as the input was aligned.
  const std::size_t at = r.out.find("--scanner ");
  REQUIRE(at != std::string::npos);
  std::string text = r.out.substr(at + 10);
  text = text.substr(0, text.find('\n'));
  const std::size_t c1 = text.find(','), c2 = text.find(',', c1 + 1);
  AlignOptions ao;
  ao.scanner = Vec3{std::stod(text.substr(0, c1)), std::stod(text.substr(c1 + 1, c2 - c1 - 1)),
                    std::stod(text.substr(c2 + 1))};
  const Alignment ain = align_cloud(in).alignment, aout = align_cloud(out, ao).alignment;
  CHECK(distance(ain.root, aout.root) < 1e-4);
  CHECK(std::abs(ain.angle - aout.angle) < 1e-9);
  // Same input, same bytes.
  REQUIRE(cli_test::run_ramus_shell("-q symmetrize " + scan + " -o " + dir + "/sym2.ply").status ==
          0);
  CHECK(cli_test::slurp(dir + "/sym.ply") == cli_test::slurp(dir + "/sym2.ply"));
  CHECK(cli_test::run_ramus_shell("symmetrize " + scan + " -o " + dir + "/x.obj").status == 1);
  CHECK(
      cli_test::run_ramus_shell("symmetrize " + dir + "/missing.xyz -o " + dir + "/x.ply").status ==
      1);
  CHECK(cli_test::run_ramus_shell("symmetrize " + scan + " -o " + dir + "/x.ply --scanner 1,2")
            .status == 1);
  CHECK(cli_test::run_ramus_shell("symmetrize").status == 2);
}
