// Branch tips carried out to the last samples ahead of them (reconstruct/bsg/tip_extension.h).
#include <catch2/catch.hpp>
#include <cmath>

#include "reconstruct/bsg/kdtree.h"
#include "reconstruct/bsg/tip_extension.h"

using namespace ramus::bsg;

namespace {

// A vertical chain of `n` nodes from the origin, `step` apart, radius 0.005.
Bsg stem(int n, double step) {
  Bsg b;
  for (int i = 0; i < n; ++i) {
    b.pos.push_back(Eigen::Vector3d(0, 0, step * i));
    b.parent.push_back(i == 0 ? kNone : std::uint32_t(i - 1));
    b.vertex.push_back(std::uint32_t(i));
    b.weight.push_back(1.0 - double(i) / n);
    b.radius.push_back(0.005);
    b.mass.push_back(1);
  }
  return b;
}

// Samples every `spacing` along the z axis from z0 to z1, `jitter` off the axis in turn.
void line(std::vector<Eigen::Vector3d>& out, double z0, double z1, double spacing, double jitter) {
  int k = 0;
  for (double z = z0; z <= z1 + 1e-9; z += spacing, ++k)
    out.emplace_back((k % 2 ? 1 : -1) * jitter, (k % 3 - 1) * jitter, z);
}

// extend_tips on `b` with a voxel of 0.01: the number of tips moved.
std::size_t walk(Bsg& b, const std::vector<Eigen::Vector3d>& samples, double max_length = 30) {
  TipExtensionParams p;
  p.spacing = 0.01;
  p.max_length = max_length;
  return extend_tips(b, samples, PointIndex(samples), p);
}

// Walks `b` and checks that nothing moved.
void check_stays(Bsg b, const std::vector<Eigen::Vector3d>& samples) {
  const std::vector<Eigen::Vector3d> before = b.pos;
  CHECK(walk(b, samples) == 0);
  CHECK(b.pos == before);
}

}  // namespace

TEST_CASE("tip extension: a tip walks to the last samples of its branch", "[reconstruct]") {
  // The chain ends at 0.2; the branch's samples go on to 0.3 (a voxel of 0.01).
  Bsg b = stem(5, 0.05);
  std::vector<Eigen::Vector3d> samples;
  line(samples, 0, 0.3, 0.01, 0.002);
  CHECK(walk(b, samples) == 1);
  // The tip moved to within a voxel of the last sample, on the axis; the chain is as it was.
  REQUIRE(b.size() == 5);
  CHECK(b.pos[4].z() > 0.29);
  CHECK(b.pos[4].head<2>().norm() < 0.003);
  CHECK(b.parent[4] == 3);
  CHECK(b.pos[3].z() == Approx(0.15));
}

TEST_CASE("tip extension: nothing ahead, nothing moves", "[reconstruct]") {
  std::vector<Eigen::Vector3d> samples;
  line(samples, 0, 0.2, 0.01, 0.002);
  check_stays(stem(5, 0.05), samples);
}

TEST_CASE("tip extension: samples of another branch ahead are not taken", "[reconstruct]") {
  // A stem to 0.2, and a second branch that passes just above its tip across it, along x, with
  // its own chain: the stem's tip must not climb onto it.
  Bsg b = stem(5, 0.05);
  const std::uint32_t root = 0;
  for (int i = 0; i <= 6; ++i) {
    b.pos.push_back(Eigen::Vector3d(-0.15 + 0.05 * i, 0, 0.23));
    b.parent.push_back(i == 0 ? root : std::uint32_t(b.size() - 1));
    b.vertex.push_back(kNone);
    b.weight.push_back(0.1);
    b.radius.push_back(0.005);
    b.mass.push_back(1);
  }
  std::vector<Eigen::Vector3d> samples;
  line(samples, 0, 0.2, 0.01, 0.002);
  for (double x = -0.15; x <= 0.15 + 1e-9; x += 0.01) samples.emplace_back(x, 0, 0.23);
  check_stays(b, samples);
}

TEST_CASE("tip extension: a tip follows its branch round a gentle bend", "[reconstruct]") {
  // Samples go on from the tip at 0.2 along an arc of radius 0.5 that bends towards +x.
  Bsg b = stem(5, 0.05);
  std::vector<Eigen::Vector3d> samples;
  line(samples, 0, 0.2, 0.01, 0.0);
  const double R = 0.5;
  for (double a = 0.02; a <= 0.6; a += 0.02)
    samples.emplace_back(R - R * std::cos(a), 0, 0.2 + R * std::sin(a));
  CHECK(walk(b, samples, 100) == 1);
  const Eigen::Vector3d end(R - R * std::cos(0.58), 0, 0.2 + R * std::sin(0.58));
  CHECK((b.pos[4] - end).norm() < 0.03);
}
