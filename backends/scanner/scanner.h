// The simulated terrestrial laser scanner: ray casts a tree's mesh from one or more stations on
// a regular angular grid, with occlusion (nearest hit only), the density falloff with range that
// angular sampling implies (spacing grows linearly with range), an optional range limit, and
// Gaussian range noise; optionally a beam of finite width (mixed-pixel echoes at edges, where a
// footprint covers a branch and what lies behind it) and stations that are registered with an
// error. Used to make clouds with a known skeleton for the reconstruction tests.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "core/point_cloud.h"
#include "core/skeleton.h"
#include "core/vec3.h"

namespace ramus::scanner {

struct ScanOptions {
  // Station positions in world coordinates. Empty: one station on the -y side at the height of
  // a tripod (1.5 % of the tree's height above its base), 1.5 tree heights away.
  std::vector<Vec3> from;
  double noise = 0.0;         // standard deviation of the range error
  double density = 2000.0;    // points per unit area on a surface facing the station at the
                              // distance of the tree's centre
  double max_range = 0.0;     // returns farther than this are lost (0: no limit)
  double angular_step = 0.0;  // radians between rays; > 0 replaces the step `density` implies
  bool leaves = false;        // also scan the leaf cards
  // Hits on triangles from this index on are kept with probability `sparse_keep` only (the
  // ground of a forest plot, which would otherwise outnumber the trees' points many times).
  std::uint32_t sparse_from = 0xffffffffu;
  double sparse_keep = 1.0;
  // The beam. A real beam is a narrow cone: its footprint at range t is beam_diameter +
  // t * beam_divergence across (both 0: a line, one hit per ray). A footprint is sampled by
  // seven rays (its centre and six around it, an equal share of its area each); their hits
  // group into echoes, hits less than range_resolution apart along the beam in one echo (0: all
  // hits of a beam are one echo, as with a phase-shift scanner), and each echo that covers at
  // least min_echo_fraction of the footprint returns one point on the beam's centre line at its
  // hits' mean range. Where a branch's edge and a surface behind it share a footprint the point
  // lies between them (a "mixed pixel"), and a branch's outline widens by what a partly covered
  // footprint still returns. docs/reconstruction.md, "Accuracy".
  double beam_divergence = 0.0;  // radians, full angle
  double beam_diameter = 0.0;    // at the scanner's exit
  double range_resolution = 0.0;
  double min_echo_fraction = 0.25;
  // Each station after the first is shifted by a random offset of this standard deviation per
  // axis (the co-registration error of a multi-station scan; the first station is the frame).
  double registration_error = 0.0;
  std::uint64_t max_rays = 200'000'000;  // per station; the angular step grows to respect it
  std::uint64_t seed = 1;
};

struct ScanResult {
  PointCloud cloud;  // scanner = the first station
  std::uint64_t rays = 0;
  std::vector<std::uint32_t> triangle;  // per point: the index of the triangle its ray hit
};

struct ScanError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Scans triangles (world positions, index triples).
ScanResult scan_triangles(const std::vector<Vec3>& vertices,
                          const std::vector<std::uint32_t>& indices, const ScanOptions& options);

// Appends the triangles scan_skeleton casts at (bark tubes, then the leaf cards when `leaves`) in
// world coordinates; indices are shifted by the vertices already in `vertices`.
void append_scanned_triangles(const Skeleton& skeleton, bool leaves, std::vector<Vec3>& vertices,
                              std::vector<std::uint32_t>& indices);

// Meshes the skeleton with the mesh back end (bark tubes, leaves when asked) and scans it.
ScanResult scan_skeleton(const Skeleton& skeleton, const ScanOptions& options);

// Ground truth for wood/leaf separation: per point of `scan` = scan_skeleton(skeleton, options),
// 1 where the ray hit a leaf card, 0 where it hit bark. Meshes the skeleton again, as
// scan_skeleton does, to find where the leaf triangles start.
std::vector<std::uint8_t> leaf_returns(const Skeleton& skeleton, const ScanResult& scan);

// Parses "x,y,z".
Vec3 parse_position(const std::string& text);

}  // namespace ramus::scanner
