// build_tree_mesh: Skeleton -> TreeMesh, and the levels of detail. LOD k halves the radial
// segments k times (never below 3), drops branch chains thinner than a growing fraction of the
// trunk (with everything growing from them), and keeps every 2^k-th leaf enlarged by sqrt(2^k)
// so the crown keeps its leaf area and silhouette.
#include <algorithm>
#include <cmath>
#include <limits>

#include "mesh/builders.h"
#include "mesh/local_origin.h"

namespace ramus::mesh {
namespace {

void check_options(const MeshOptions& o, int lod) {
  auto bad = [](const std::string& what) { throw MeshError("invalid mesh option: " + what); };
  if (!(std::isfinite(o.pipe_exponent) && o.pipe_exponent >= 0)) bad("pipe exponent must be >= 0");
  if (o.pipe_exponent > 0 && o.pipe_exponent < 1) bad("pipe exponent must be at least 1");
  if (!(std::isfinite(o.min_radius) && o.min_radius >= 0)) bad("minimum radius must be >= 0");
  if (o.min_radial_segments < 3 || o.max_radial_segments < o.min_radial_segments ||
      o.max_radial_segments > 256) {
    bad("radial segments must satisfy 3 <= min <= max <= 256");
  }
  if (!(std::isfinite(o.leaf_scale) && o.leaf_scale > 0)) bad("leaf scale must be > 0");
  if (!(std::isfinite(o.leaf_aspect) && o.leaf_aspect > 0)) bad("leaf aspect must be > 0");
  if (o.lod_count < 1 || o.lod_count > 8) bad("LOD count must be 1..8");
  if (o.wind && o.wind_rig.max_joints < 2) bad("the wind skin needs at least 2 joints");
  if (o.wind && !(o.wind_rig.period >= 2 && std::isfinite(o.wind_rig.period)))
    bad("the wind period must be at least 2 s");
  if (lod < 0 || lod > 7) bad("LOD index must be 0..7");
}

// Fraction of the thickest radius below which LOD k drops a chain: none at LOD0, then 2%, 6%, ...
double drop_fraction(int lod) { return lod == 0 ? 0.0 : 0.02 * std::pow(3.0, lod - 1); }

void check_result(const TreeMesh& m) {
  for (const MeshPart* part : {&m.bark, &m.leaves}) {
    if (part->positions.size() >= std::numeric_limits<std::uint32_t>::max()) {
      throw MeshError("the mesh has more vertices than 32-bit indices can address");
    }
    for (const Vec3f& v : part->positions) {
      if (!is_finite(v))
        throw MeshError("coordinates overflow single precision (is the skeleton scaled sensibly?)");
    }
  }
}

TreeMesh build_level(const Skeleton& s, const PreparedSkeleton& p, const WindField& wind,
                     const MeshOptions& options, int lod, MeshReport& report) {
  TreeMesh mesh;
  mesh.name = options.name + "_LOD" + std::to_string(lod);
  TubeParams tp;
  tp.max_segments = std::max(options.min_radial_segments, options.max_radial_segments >> lod);
  tp.min_segments = options.min_radial_segments;
  tp.caps = options.caps;
  tp.count_repairs = lod == 0;
  const double drop_below = p.max_radius * drop_fraction(lod);
  std::vector<std::uint8_t> dropped(p.chains.size(), 0);
  for (std::uint32_t c = 0; c < p.chains.size(); ++c) {
    const Chain& ch = p.chains[c];
    const bool parent_gone = ch.parent_chain != kNoChain && dropped[ch.parent_chain];
    const double r = p.radius[ch.nodes.size() > 1 ? ch.nodes[1] : ch.nodes[0]];
    dropped[c] = parent_gone || (ch.parent_chain != kNoChain && r < drop_below);
    if (dropped[c]) continue;
    if (!add_chain_tube(s, p, c, wind, tp, mesh.bark, report) && lod == 0) ++report.skipped_chains;
  }
  const std::size_t stride = std::size_t(1) << lod;
  const double scale = std::sqrt(double(stride));
  for (std::size_t i = 0; i < s.organs.size(); ++i) {
    if (!s.organs[i].vertices.empty()) {  // a polygon is the organ's shape: kept at every level
      add_organ_polygon(s, p, i, wind, mesh.surfaces);
      continue;
    }
    if (i % stride != 0) continue;
    if (!add_organ_cards(s, p, i, wind, options, scale, mesh.leaves) && lod == 0) {
      ++report.skipped_organs;
    }
  }
  check_result(mesh);
  return mesh;
}

// The skeleton to mesh: `s` itself, or (for a georeferenced tree) its copy in `storage` moved
// to the local origin in double precision, before any coordinate is narrowed to float.
const Skeleton& local_skeleton(const Skeleton& s, const Vec3& origin, Skeleton& storage) {
  if (origin == Vec3{}) return s;
  storage = relative_to(s, origin);
  return storage;
}

}  // namespace

std::vector<std::string> MeshReport::warnings() const {
  std::vector<std::string> w;
  auto n = [](std::size_t k) { return std::to_string(k); };
  if (radii_synthesized)
    w.push_back("the skeleton has no radii; using the pipe model from thin tips");
  if (clamped_radii) {
    w.push_back(n(clamped_radii) + " node radii were zero, negative or below " +
                std::to_string(min_radius) + " and were clamped to it");
  }
  if (merged_nodes)
    w.push_back(n(merged_nodes) + " zero-length segments (coincident nodes) were merged");
  if (skipped_chains) w.push_back(n(skipped_chains) + " branches of zero length have no tube");
  if (skipped_organs)
    w.push_back(n(skipped_organs) + " organs of zero or negative size were left out");
  return w;
}

namespace {

// Levels first..last of the tree, from one preparation of the skeleton.
std::vector<TreeMesh> build_levels(const Skeleton& s, const MeshOptions& options, int first,
                                   int last, MeshReport* report) {
  MeshReport local;
  MeshReport& r = report ? *report : local;
  const Vec3 origin = local_origin(s);
  Skeleton storage;
  const Skeleton& at_origin = local_skeleton(s, origin, storage);
  const PreparedSkeleton p = prepare_skeleton(at_origin, options, r);
  const WindField wind = make_wind_field(at_origin, p);
  std::vector<TreeMesh> lods;
  WindRig rig;
  if (options.wind) rig = make_wind_rig(at_origin, p, wind, options.wind_rig);
  for (int k = first; k <= last; ++k) {
    lods.push_back(build_level(at_origin, p, wind, options, k, r));
    lods.back().origin = origin;
    lods.back().wind_rig = rig;
  }
  return lods;
}

}  // namespace

TreeMesh build_tree_mesh(const Skeleton& s, const MeshOptions& options, int lod,
                         MeshReport* report) {
  check_options(options, lod);
  return std::move(build_levels(s, options, lod, lod, report).front());
}

std::vector<TreeMesh> build_tree_lods(const Skeleton& s, const MeshOptions& options,
                                      MeshReport* report) {
  check_options(options, 0);
  return build_levels(s, options, 0, options.lod_count - 1, report);
}

}  // namespace ramus::mesh
