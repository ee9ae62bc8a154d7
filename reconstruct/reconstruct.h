// Skeleton reconstruction from laser scans: PointCloud -> one Skeleton per tree.
//
// Implements Livny, Yan, Olson, Chen, Zhang & El-Sana, "Automatic Reconstruction of Tree Skeletal
// Structures from Point Clouds", ACM Trans. Graph. 29(6) (SIGGRAPH Asia 2010), sections 4.1-4.3:
//   4.1 tree bases from the density of points projected on the ground, terrain removal, and one
//       initial Branch-Structure Graph (BSG) per tree from a multi-root Dijkstra forest;
//   4.2 importance weights, the orientation field (Eq. 1 + 2), the smoothed embedding (Eq. 3 + 4)
//       and reweighted re-runs of Dijkstra until the forest stops changing;
//   4.3 radii (Eq. 6 + 7), removal of edges whose generalized cylinders overlap, degree-2
//       collapse, and leaves synthesized at leaf nodes.
// The stages live in reconstruct/bsg/; docs/reconstruction.md describes the method
// and its parameters. Several trees in one scan are separated without pre-segmentation.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/point_cloud.h"
#include "core/skeleton.h"
#include "core/vec3.h"
#include "reconstruct/wood/wood_separation.h"

namespace ramus {

// Lengths are in the cloud's units (metres for real scans). 0 means "choose from the data".
struct ReconstructOptions {
  // Points are merged on a voxel grid of this edge length before the graph is built.
  double voxel_size = 0;  // auto: from the median point spacing and the cloud's height
  // Auto voxel: this many median point spacings, but at least this fraction of the height. One
  // spacing keeps twigs of 1-1.3 cm apart from their neighbours; the axis projection below is
  // what lets thick branches at this resolution still collapse to one chain.
  double voxel_spacings = 1.0;
  double voxel_height_floor = 1.0 / 1000;
  int neighbours = 10;  // k of the k-nearest-neighbour graph (4.1)
  double max_gap = 0;   // largest gap bridged between graph components; auto: 8% of height
  // Reach of a hidden limb (a component at least 10 voxels across, bridged once nothing else can
  // be) as a multiple of max_gap; 1 or less turns the longer reach off.
  double hidden_limb_reach = 3;
  // Thickness-adaptive projection onto branch axes before the Dijkstra forest: the ball around
  // each cell of grids of 2, 4, 8, ... voxels (this many levels; 0 = off) grows level by level
  // until its samples are linear (lambda_1 >= axis_linearity * lambda_2); the vertex moves onto
  // that ball's principal line, refitted axis_passes - 1 times from its projection
  // (docs/reconstruction.md, Deviations).
  int axis_levels = 4;
  double axis_linearity = 4.0;
  int axis_passes = 2;
  int contraction_steps = 3;  // neighbour-mean steps after it: smooth the projected samples

  // Tree bases (4.1).
  bool remove_terrain = true;  // drop the lowest layer of points (the ground) before the graph
  double ground_band = 0;      // thickness of the terrain layer; auto: 1.5% of height (>= voxel)
  double base_cell = 0;        // 2D density grid cell; auto: 1% of height (>= voxel)
  double base_slab = 0;        // height of the slab above ground whose density finds trunks;
                               // auto: 10% of the cloud's height
  double max_trunk_width = 0;  // wider dense clusters (walls, hedges) are not trees; auto: 30%
                               // of the height of the points standing above the cluster
  double min_tree_separation = 0;  // weaker base clusters nearer than this to a stronger one are
                                   // low branches of its tree; auto: 10% of the height
  std::vector<Vec3> roots;  // world positions of tree bases; when set, base detection is skipped
  // Points with fewer than two others within four voxels are ignored (docs/reconstruction.md,
  // "Stray points": mixed-pixel returns between a twig's edge and what lies behind it), and with
  // `stray_cluster` > 1 those of clusters of fewer points, linked by steps within four voxels,
  // after the terrain ("Runs of a few": 5 for a phase-shift scanner's runs of mixed points; off
  // by default, as it cost some real scans).
  bool remove_stray = true;
  std::size_t stray_cluster = 1;

  // Refinement (4.2).
  int max_iterations = 2;          // Dijkstra + refinement rounds at most (paper: 2-3 suffice)
  double convergence = 0.01;       // stop when fewer than this fraction of parents change
  double reweight_strength = 0.5;  // aligned edges cost (1 - strength |cos|) of their weight

  // Inflation (4.3).
  double allometry_exponent = 2.5;  // r_parent^e / r_child^e = c_parent / c_child (Eq. 5)
  double overlap_fraction = 0.5;    // collapse an edge whose cylinder is covered more than this
  double min_branch_length = 0;     // drop leaf twigs shorter than this; auto: 10 voxels
  double min_cylinder_radius = 0;   // cylinders are at least this thick when overlaps are
                                    // measured (zig-zags across thin branches); auto: 2 voxels

  // Centre lines (docs/reconstruction.md): after 4.3, every node moves to the axis of a robust
  // circle fitted to its cross-section, where the fit is good, and takes the fitted radius.
  bool centre_lines = true;
  // With them, chains they put on one axis (the BSG's parallel paths up a thick stem's bark, one
  // to each branch it carries) are joined into one (docs/reconstruction.md, Centre lines, 11).
  bool join_coincident = true;
  // Tips (docs/reconstruction.md): every branch tip walks on along its branch while samples no
  // other edge claims lie ahead of it (the stages before pull tips back by a voxel or two each).
  bool extend_tips = true;

  // Leaves (4.3, fine geometry synthesis).
  bool leaves = true;
  int min_leaves = 20, max_leaves = 50;
  double leaf_sphere = 0;  // radius of the sphere leaves are scattered in; auto: 2 voxels
  std::uint64_t seed = 1;

  // Foliage in the scan (docs/wood-separation.md): kept, removed by the unsupervised wood/leaf
  // separation before anything else, or removed when the separation finds it a large share.
  LeafHandling leaves_in_scan = LeafHandling::kKeep;
};

struct ReconstructTimings {
  double bases = 0, graph = 0, forest = 0, refine = 0, inflate = 0, total = 0;  // seconds
};

struct ReconstructCounts {
  std::size_t input_points = 0;
  std::size_t dropped_points = 0;  // non-finite coordinates
  std::size_t outlier_points = 0;  // far outside the rest of the cloud (ignored)
  std::size_t terrain_points = 0;
  std::size_t stray_points = 0;  // alone in the air (ReconstructOptions::remove_stray)
  std::size_t graph_vertices = 0;
  std::size_t graph_edges = 0;
  std::size_t bridged_gaps = 0;      // components joined through their closest pair
  std::size_t unreached_points = 0;  // farther than max_gap from every tree
  int iterations = 0;                // Dijkstra + refinement rounds run
  std::size_t skeleton_nodes = 0;    // over all trees
};

struct ReconstructResult {
  std::vector<Skeleton> trees;            // world coordinates, one per tree base
  std::vector<std::uint32_t> point_tree;  // tree of every input point; kNoTree if none
  double voxel_size = 0;                  // the voxel size used
  ReconstructTimings timings;
  ReconstructCounts counts;
  std::vector<std::string> notes;  // why a result is empty, what was dropped
  static constexpr std::uint32_t kNoTree = 0xffffffffu;
};

// Thrown for input that cannot be reconstructed at all (an empty cloud, no finite point).
struct ReconstructError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Runs the whole pipeline. A cloud without any tree (a building, bare ground, a plane) gives an
// empty `trees` and a note saying why. Deterministic: same cloud and options -> same result.
ReconstructResult reconstruct(const PointCloud& cloud, const ReconstructOptions& options = {});

}  // namespace ramus
