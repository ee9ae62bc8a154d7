// Skeleton against skeleton (reconstruct/bsg/compare.h): the scores over the wood the scan saw.
// A truth sample counts as seen when scan points on its bark cover 60 degrees of its
// circumference; the recall and centre-line error over the seen samples must ignore the rest.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "core/rng.h"
#include "reconstruct/bsg/compare.h"

using namespace ramus;

namespace {

// A vertical stem of radius r from z = 0 to z = 2, in nodes 0.1 apart.
Skeleton stem(double r, double dx = 0) {
  Skeleton s;
  for (int k = 0; k <= 20; ++k) {
    SkeletonNode n;
    n.position = {dx, 0, 0.1 * k};
    n.radius = r;
    n.parent = k == 0 ? kNoParent : std::uint32_t(k - 1);
    s.nodes.push_back(n);
  }
  return s;
}

// Points on the bark at radius `at` between heights z0 and z1, over the arc [a0, a1] (radians),
// with 1 mm of noise; the cloud's offset is (5, 5, 0), as a scan's recentring would make it.
void add_bark(PointCloud& cloud, double at, double z0, double z1, double a0, double a1,
              std::uint64_t seed) {
  cloud.offset = {5, 5, 0};
  Rng rng(seed);
  for (int i = 0; i < 4000; ++i) {
    const double z = z0 + (z1 - z0) * rng.uniform01();
    const double a = a0 + (a1 - a0) * rng.uniform01();
    const double rr = at + 0.001 * (rng.uniform01() - 0.5);
    cloud.positions.push_back(
        Vec3f(float(rr * std::cos(a) - 5), float(rr * std::sin(a) - 5), float(z)));
  }
}

CompareOptions options(const PointCloud* scan) {
  CompareOptions o;
  o.spacing = 0.02;
  o.radius_classes = {0.05, 0.2};
  o.scan = scan;
  return o;
}

}  // namespace

TEST_CASE("compare: the lower half seen all round, the upper half on 30 degrees", "[compare]") {
  const double r = 0.1;
  PointCloud scan;
  add_bark(scan, r, 0.0, 1.0, 0, 2 * M_PI, 1);
  add_bark(scan, r, 1.0, 2.0, 0, M_PI / 6, 2);
  // A reconstruction 1 cm beside the lower half, 5 cm beside the upper half.
  Skeleton rec = stem(r, 0.01);
  for (SkeletonNode& n : rec.nodes) {
    if (n.position.z > 1.05) n.position.x = 0.05;
  }
  const SkeletonComparison c = compare_skeletons({stem(r)}, {rec}, options(&scan));
  INFO("seen " << c.seen_fraction << " recall seen " << c.recall_seen << " median seen "
               << c.centre_error_median_seen << " median " << c.centre_error_median);
  CHECK(c.seen_fraction > 0.45);
  CHECK(c.seen_fraction < 0.55);
  CHECK(c.recall_seen == 1.0);
  REQUIRE(c.centre_error.size() == 1);
  CHECK(c.centre_error[0].seen > 0);
  CHECK(c.centre_error[0].seen < c.centre_error[0].samples);
  // Over the seen (lower) half the error is 0.1 r; over all samples the upper half counts too.
  CHECK(c.centre_error[0].median_seen == Approx(0.1).margin(0.01));
  CHECK(c.centre_error_median_seen == Approx(0.1).margin(0.01));
  CHECK(c.centre_error[0].median > 0.15);
}

TEST_CASE("compare: points off the bark do not make a stem seen", "[compare]") {
  PointCloud scan;
  add_bark(scan, 0.3, 0.0, 2.0, 0, 2 * M_PI, 3);  // a sleeve three radii out
  const SkeletonComparison c = compare_skeletons({stem(0.1)}, {stem(0.1)}, options(&scan));
  CHECK(c.seen_fraction == 0.0);
  CHECK(c.recall_seen == 0.0);
  CHECK(c.centre_error[0].seen == 0);
  CHECK(c.recall == 1.0);
}

TEST_CASE("compare: without a scan the seen scores stay zero", "[compare]") {
  const SkeletonComparison c = compare_skeletons({stem(0.1)}, {stem(0.1, 0.02)}, options(nullptr));
  CHECK(c.seen_fraction == 0.0);
  CHECK(c.centre_error[0].seen == 0);
  CHECK(c.centre_error[0].median == Approx(0.2).margin(0.01));
}

TEST_CASE("compare: the kept samples are the ones behind the class medians", "[compare]") {
  const double r = 0.1;
  PointCloud scan;
  add_bark(scan, r, 0.0, 1.0, 0, 2 * M_PI, 4);
  Skeleton rec = stem(r, 0.01);
  for (SkeletonNode& n : rec.nodes) {
    if (n.position.z > 1.05) n.position.x = 0.05;
  }
  CompareOptions o = options(&scan);
  CHECK(compare_skeletons({stem(r)}, {rec}, o).centre_samples.empty());
  o.keep_samples = true;
  const SkeletonComparison c = compare_skeletons({stem(r)}, {rec}, o);
  REQUIRE(c.centre_error.size() == 1);
  REQUIRE(c.centre_samples.size() == c.centre_error[0].samples);
  std::vector<double> seen;
  for (const CentreSample& q : c.centre_samples) {
    CHECK(q.radius == Approx(r));
    CHECK(q.direction.z == Approx(1.0));
    // Each error is the distance to the reconstruction over the radius, as placed above (the
    // edge from 1.0 to 1.1 m crosses between the two offsets).
    if (q.position.z < 0.99) CHECK(q.error == Approx(0.1).margin(1e-6));
    if (q.position.z > 1.11) CHECK(q.error == Approx(0.5).margin(1e-6));
    if (!q.seen) continue;
    seen.push_back(q.error);
    // Seen: the lower half, whose bark is scanned (the slab reaches 2.5 cm across its top).
    CHECK(q.position.z < 1.03);
  }
  CHECK(seen.size() == c.centre_error[0].seen);
  std::sort(seen.begin(), seen.end());
  CHECK(seen[seen.size() / 2] == Approx(c.centre_error[0].median_seen).margin(1e-6));
}

TEST_CASE("compare: further fixed distances are scored in the same pass", "[compare]") {
  // A stem 3 cm beside the truth: every sample is 3 cm from the other's nearest.
  CompareOptions o;
  o.spacing = 0.01;
  o.distance = 0.05;
  o.distances = {0.02, 0.05, 0.1};
  const SkeletonComparison c = compare_skeletons({stem(0.1)}, {stem(0.1, 0.03)}, o);
  REQUIRE(c.precision_within.size() == 3);
  REQUIRE(c.recall_within.size() == 3);
  CHECK(c.precision_within == std::vector<double>{0, 1, 1});
  CHECK(c.recall_within == std::vector<double>{0, 1, 1});
  // The one fixed distance and the same one in the list agree.
  CHECK(c.precision_within[1] == c.precision_distance);
  CHECK(c.recall_within[1] == c.recall_distance);
  o.distances.clear();
  CHECK(compare_skeletons({stem(0.1)}, {stem(0.1, 0.03)}, o).precision_within.empty());
}
