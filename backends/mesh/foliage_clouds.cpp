#include "backends/mesh/foliage_clouds.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/rng.h"

namespace ramus::mesh {
namespace {

double squared(const Vec3& v) { return dot(v, v); }

// k-means++ (Arthur & Vassilvitskii 2007): the first centre a random point, each next one a
// point drawn with probability proportional to its squared distance to the nearest centre so far.
std::vector<Vec3> seed_centres(const std::vector<Vec3>& points, int k, Rng& rng) {
  std::vector<Vec3> centres{points[rng.below(points.size())]};
  std::vector<double> nearest(points.size(), std::numeric_limits<double>::infinity());
  while (int(centres.size()) < k) {
    double total = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      nearest[i] = std::min(nearest[i], squared(points[i] - centres.back()));
      total += nearest[i];
    }
    if (total <= 0) break;  // fewer distinct points than clouds
    double pick = rng.uniform(0, total);
    std::size_t i = 0;
    for (; i + 1 < points.size() && pick >= nearest[i]; ++i) pick -= nearest[i];
    centres.push_back(points[i]);
  }
  return centres;
}

std::size_t nearest_centre(const Vec3& p, const std::vector<Vec3>& centres) {
  std::size_t best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < centres.size(); ++c) {
    const double d = squared(p - centres[c]);
    if (d < best_d) {
      best_d = d;
      best = c;
    }
  }
  return best;
}

}  // namespace

int foliage_cloud_count(std::size_t cards) {
  if (cards == 0) return 0;
  return std::clamp(int(std::lround(std::sqrt(double(cards)))), 1, kMaxFoliageClouds);
}

std::vector<FoliageCloud> foliage_clouds(const MeshPart& leaves, std::uint64_t seed) {
  const std::size_t faces = leaves.positions.size() / 4;
  if (faces == 0) return {};
  std::vector<Vec3> points(faces);
  for (std::size_t f = 0; f < faces; ++f) {
    Vec3 sum;
    for (int k = 0; k < 4; ++k) sum = sum + Vec3(leaves.positions[4 * f + k]);
    points[f] = sum * 0.25;
  }
  // Each card has a front and a back face at the same place: half the faces are cards.
  Rng rng = Rng::stream(seed, 0xf011a9e);
  std::vector<Vec3> centres = seed_centres(points, foliage_cloud_count(faces / 2), rng);
  std::vector<std::size_t> cloud(faces, centres.size());
  for (int iteration = 0; iteration < 100; ++iteration) {
    bool changed = false;
    for (std::size_t f = 0; f < faces; ++f) {
      const std::size_t c = nearest_centre(points[f], centres);
      changed = changed || c != cloud[f];
      cloud[f] = c;
    }
    if (!changed) break;
    std::vector<Vec3> sum(centres.size());
    std::vector<std::size_t> count(centres.size(), 0);
    for (std::size_t f = 0; f < faces; ++f) {
      sum[cloud[f]] = sum[cloud[f]] + points[f];
      ++count[cloud[f]];
    }
    for (std::size_t c = 0; c < centres.size(); ++c)
      if (count[c] > 0) centres[c] = sum[c] * (1.0 / double(count[c]));
  }
  std::vector<double> radius(centres.size(), -1.0);
  for (std::size_t f = 0; f < faces; ++f)
    for (int k = 0; k < 4; ++k)
      radius[cloud[f]] =
          std::max(radius[cloud[f]], length(Vec3(leaves.positions[4 * f + k]) - centres[cloud[f]]));
  std::vector<FoliageCloud> out;
  for (std::size_t c = 0; c < centres.size(); ++c)
    if (radius[c] >= 0) out.push_back({centres[c], radius[c]});  // clouds that kept faces
  return out;
}

}  // namespace ramus::mesh
