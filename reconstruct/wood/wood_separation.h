// Unsupervised wood/leaf separation of a laser scan: which points are bark (stems, branches,
// twigs) and which are foliage. Skeleton reconstruction (Livny et al. 2010) assumes wood points
// (its section 6 and Figure 13 show leafy scans failing), so leafy summer scans are separated
// first: `ramus reconstruct --leaves-in-scan`, `ramus classify` (docs/wood-separation.md).
//
// The method (docs/wood-separation.md), one stage per file in reconstruct/wood/:
//  1. covariance features (features.h, Demantke et al. 2011): the score of a point is its
//     planarity at r / 2 times its scattering at 2r, each computed on a grid a quarter of that
//     scale fine (voxel_subsample.h) -- a leaf card is flat at the scale of a leaf, and the cards
//     of a cluster at different orientations make foliage volumetric at the scale of the
//     cluster, while twigs are linear at r / 2 and the bark of thick stems is not scattered at 2r;
//  2. graph smoothing: the score is averaged over the neighbourhood graph of the cells of a grid
//     r / 4 fine, a few Jacobi steps (wood and leaves come in connected regions);
//  3. unsupervised decisions: a foliage mode exists when two Gaussians fitted by EM to the scores
//     (mixture.h, as in Vicari et al. 2019) are separated (Ashman's D) and enough cells lie above
//     Otsu's threshold (otsu.h), which then splits leaf from wood -- a bark-only scan has one
//     skewed mode and loses nothing;
//  4. region growing: connected wood regions shorter than a few r, apart from the stem, are flat
//     leaf cards and turn leaf (wood forms long connected structures).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/point_cloud.h"

namespace ramus {

// What reconstruction does with foliage in a scan.
enum class LeafHandling {
  kKeep,    // reconstruct from every point (the scan is known to be wood only)
  kRemove,  // separate and reconstruct from the wood points
  kAuto,    // separate, and remove the leaves when they are a large share of the scan
};

struct WoodOptions {
  double scale = 0;         // the smaller neighbourhood radius r; 0: max(H / 100, 6 spacings)
  int smoothing_steps = 4;  // neighbour-mean steps over the graph of the fine grid
  // A foliage mode needs both: the two Gaussians separated by at least this Ashman's D, and at
  // least this share of the cells above Otsu's threshold (bark-only scans: 10-14%).
  double min_separation = 2.15;
  double min_leaf_share = 0.2;
  // Connected wood regions whose bounding box diagonal is shorter than this many r are leaf
  // cards (the largest region, the stem, is always wood).
  double min_region_extent = 4.0;
  // kAuto removes the leaves when at least this fraction of the points is classified leaf, the
  // mixture found a foliage mode, and the scan resolves leaves at all: its median point spacing
  // is at most this fraction of its height (sparse airborne scans, ~H / 60, do not: their crown
  // of bare twigs scatters like foliage).
  double auto_leaf_fraction = 0.25;
  double auto_max_spacing = 1.0 / 150;
};

struct WoodSeparation {
  std::vector<std::uint8_t> wood;  // per input point: 1 wood, 0 leaf or non-finite
  std::vector<float> leaf_score;   // per input point: the smoothed scattering (0 if non-finite)
  std::size_t finite_points = 0;
  std::size_t leaf_points = 0;
  double leaf_fraction = 0;  // leaf_points / finite_points
  double scale = 0;          // the radius r used
  double spacing = 0;        // median point spacing
  double height = 0;         // extent of the finite points along z
  double upper_share = 0;    // share of the cells above Otsu's threshold
  double threshold = 0;      // scores above this are leaf (infinity when no leaf mode)
  double separation = 0;     // Ashman's D of the fitted mixture
  bool leaf_mode = false;    // the mixture found a separate foliage mode
  std::vector<std::string> notes;
};

struct WoodError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Classifies every point. Deterministic (same cloud and options -> same bytes). Throws WoodError
// for an empty cloud; a cloud with too few finite points to measure is all wood, with a note.
WoodSeparation separate_wood(const PointCloud& cloud, const WoodOptions& options = {});

// kAuto's decision (docs/wood-separation.md): whether to remove the points classified leaf, and
// a note giving the evidence (leaf fraction, Ashman's D, share above Otsu's threshold, spacing).
struct LeafDecision {
  bool remove = false;
  std::string note;
};
LeafDecision decide_leaf_removal(const WoodSeparation& ws, LeafHandling handling,
                                 const WoodOptions& options = {});

// The points where keep[i] != 0, with their optional channels.
PointCloud select_points(const PointCloud& cloud, const std::vector<std::uint8_t>& keep);

}  // namespace ramus
