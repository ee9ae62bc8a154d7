// Centre lines: every skeleton node moved onto the axis of the wood around it, and its radius
// measured there. The shortest paths of the BSG (Livny et al. 2010, 4.1) and the flood fill run
// along the scanned surface of thick stems, so without this step a trunk's skeleton sits up to
// its radius away from the true axis (issue 19). The cross-section of a node is the slab of
// points perpendicular to the local branch direction; a robust circle fit in the slab's plane
// (circle_fit.h, as TreeQSM and AdTree fit cylinders) gives the axis point and the radius, which
// replace the node's position and radius where the fit is good. Elsewhere (too few points, an arc
// too short, a radius implausible against the branch's) the node stays and keeps the radius the
// caller gave it (Livny 4.3's allometric one); where a chain of such nodes lies on a branch, a
// cylinder fitted along the chain or the segment between its fitted neighbours places them
// (chain_cylinders.h). The topology is never changed.
// docs/reconstruction.md, "Centre lines".
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/skeleton.h"
#include "reconstruct/bsg/bsg.h"
#include "reconstruct/bsg/kdtree.h"

namespace ramus::bsg {

// 1/sqrt(2): the radius of either child of a fork of two equal children in the pipe model
// (Livny et al. 2010, 4.3). A stem that goes on through a node keeps at least this share of the
// radius below it.
inline constexpr double kPipeChild = 0.70710678118654752;

struct CentreLineParams {
  double spacing = 0;  // point spacing of the samples (the voxel): floors every length below
  double noise = 0;    // floor of a fit's residual scale; 0: a quarter of the spacing
  // A fit is accepted when the inliers cover at least this arc (a one-sided scan sees about
  // 180 degrees of a stem, less at grazing angles) ...
  double min_coverage = 1.9;  // radians, ~110 degrees
  // ... their residual scale is at most this fraction of the radius (plus the noise floor) ...
  double max_residual = 0.2;
  double min_inliers = 0.5;  // ... at least this share of the slab's points are inliers ...
  // ... and the radius is at most this factor above the nearest fitted ancestor's (a branch does
  // not thicken outwards; a slab that cuts its parent's stem near a fork, or two limbs pressed
  // together after it, does). Chosen over the harness trees turned to six azimuths: 1.3 let
  // such circles through; below 1.13 the weeping tree's leader left its axis at a fork
  // (docs/reconstruction.md, Centre lines, step 4).
  double max_section_growth = 1.15;
  // The same bound for the continuation fits (cut across the axis of the fitted stem below) and,
  // against the thickest cross-section, for the chain cylinders: the tighter bound measured
  // worse there.
  double max_growth = 1.3;
  // ... and at most this factor above the radius hint (allometric radii are off by 2-3 x; a
  // nearly straight arc fits any huge circle).
  double max_hint_factor = 6.0;
  // Nodes whose radius hint is below this many spacings are not fitted (twigs: a circle needs
  // points around it, and the BSG's axis projection has centred them already).
  double min_hint_spacings = 0.5;
  // A node moves at most this many fitted radii (plus two spacings): it lies on the bark or
  // near it, and a farther circle is another branch's.
  double max_shift = 1.75;
  // A slab that no circle fits but whose points fall into separate groups (two limbs side by
  // side after a fork) is fitted again with the group nearest the node alone.
  bool separate_stems = true;
  // ... and where no gap parts the two limbs' arcs, the slab's points are split into two arcs
  // (circle_fit.h, split_two_arcs) and the node takes the circle of the nearer one when it
  // continues the axis of the stem below.
  bool split_arcs = true;
  // Unfitted nodes that continue a fitted stem are fitted again across that stem's axis.
  bool continuation_fits = true;
  // Chains with unfitted nodes get cylinders fitted along them (chain_cylinders.h).
  bool chain_cylinders = true;
  // Nodes still unfitted are fitted with their branch's radius on arcs from 60 degrees
  // (one_sided_sections.h).
  bool one_sided_sections = true;
  // A root left unfitted below a fitted stem moves onto the stem's axis continued down (the BSG
  // roots a tree at the scan's vertex nearest its base, on the bark; the flood fill roots it at
  // the base itself and turns this off).
  bool centre_roots = true;
  int passes = 2;             // refits from the moved nodes (better directions, centred balls)
  int max_slab_points = 300;  // slabs with more points are thinned evenly before the fit
};

struct CentreLineResult {
  std::vector<std::uint8_t> fitted;  // per node: moved onto a fitted axis
  std::vector<double> radius;        // per node: the fitted radius (0 where not fitted)
  std::size_t fitted_count = 0;
};

// Moves pos[v] onto the fitted axes (parent[v] = kNone for roots; any order). `radius` holds
// the current radii, the hint for the size of the cross-sections. `samples` are the points,
// `index` a PointIndex over them (the caller's, shared with the later steps), `sample_weight`
// how many input points each stands for (empty: 1 each).
CentreLineResult centre_line(std::vector<Eigen::Vector3d>& pos,
                             const std::vector<std::uint32_t>& parent,
                             const std::vector<double>& radius,
                             const std::vector<Eigen::Vector3d>& samples, const PointIndex& index,
                             const std::vector<double>& sample_weight,
                             const CentreLineParams& params);

// Splits every edge of radius >= min_radius longer than max(edge_radii x its radius,
// edge_spacings x spacing) into equal parts (new degree-2 vertices without a graph vertex), so
// that long collapsed edges, which cut the corners of curved stems, get cross-sections of their
// own. Parents stay before children.
void subdivide_long_edges(Bsg& bsg, double spacing, double min_radius, double edge_radii = 2.0,
                          double edge_spacings = 4.0);

// Removes side branches that never leave a stem: leaf chains (tip back to the fork) whose tip and
// at least three quarters of their nodes lie within 1.1 x the radius (plus two spacings) of an
// edge of another branch whose ends were both fitted. These are the shortest paths that ran along
// the bark of a thick stem beside the one that became its skeleton (issue 19: 3-9 x the true
// length on trees with 30-60 cm trunks); once the stem is centred they lie inside it, but for the
// stretch from a fork on a neighbouring limb across to the stem. Returns the number of vertices
// removed.
std::size_t drop_branches_inside_stems(Bsg& bsg, const std::vector<std::uint8_t>& fitted,
                                       double spacing);

// The rule above with the containers given: container[v] says whether the edge from v's parent
// to v is one, and only leaf chains whose tip has tip_may_go set are looked at. Returns the
// number of vertices removed.
std::size_t drop_chains_inside_edges(Bsg& bsg, const std::vector<std::uint8_t>& container,
                                     const std::vector<std::uint8_t>& tip_may_go, double spacing);

// Nodes in parent-first order (roots first, then children level by level), and each node's
// child with the largest subtree (the first of equal ones; kNone for a tip). Shared by the
// centre lines and the trunk tracking (stem_tracking.h).
void tree_order(const std::vector<std::uint32_t>& parent, std::vector<std::uint32_t>& order,
                std::vector<std::uint32_t>& main_child);

// The cross-section of the samples at x across the unit direction d: the samples within `half`
// of x along d and within `reach` of it across, as coordinates (u, v) in the frame (e1, e2) of
// perpendicular_frame(d) (bsg.h), with their weights (1 each when `weight` is empty), in the
// order the index gives them. `near` is scratch. Shared by the cross-sections and the one-sided
// sections (one_sided_sections.h).
void gather_slab(const Eigen::Vector3d& x, const Eigen::Vector3d& d, const Eigen::Vector3d& e1,
                 const Eigen::Vector3d& e2, double reach, double half, const PointIndex& index,
                 const std::vector<Eigen::Vector3d>& samples, const std::vector<double>& weight,
                 std::vector<std::uint32_t>& near, std::vector<Eigen::Vector2d>& pts,
                 std::vector<double>& w);

// The samples within `half` of x along the unit direction d and within `reach` of the line
// through x along d (the points around a piece of axis), as they are, with their weights (1 each
// when `weight` is empty), in the order the index gives them. `near` is scratch. Shared by the
// cylinders along chains (chain_cylinders.h) and the trunk tracking (stem_tracking.h).
void gather_cylinder(const Eigen::Vector3d& x, const Eigen::Vector3d& d, double reach, double half,
                     const PointIndex& index, const std::vector<Eigen::Vector3d>& samples,
                     const std::vector<double>& weight, std::vector<std::uint32_t>& near,
                     std::vector<Eigen::Vector3d>& pts, std::vector<double>& w);

// Thins a slab's points and their weights evenly (every k-th, k the smallest stride that keeps
// at most `max_points`); a slab of thousands of points fits no better than of a few hundred.
void thin_slab(std::vector<Eigen::Vector2d>& pts, std::vector<double>& w, int max_points);

// Radii after centre_line: fitted nodes take the median of the fitted radii of themselves, their
// parent and their children (one noisy slab does not make a bulge); the others below a fitted
// node keep their radii's shape (radius / the fitted ancestor's radius, at most 1) scaled to that
// ancestor's fitted radius; nodes above every fit keep theirs. A fitted radius over twice its
// parent's counts as unfitted.
void smooth_fitted_radii(const std::vector<std::uint32_t>& parent, const CentreLineResult& fit,
                         std::vector<double>& radius);

// The same on finished skeletons (the flood fill's), against the cloud's points in world
// coordinates. Returns the number of nodes moved.
std::size_t centre_skeleton(Skeleton& skeleton, const std::vector<Eigen::Vector3d>& points,
                            const CentreLineParams& params);

}  // namespace ramus::bsg
