// The pieces build_tree_mesh assembles: one tube per branch chain, one card (or two) per organ.
#pragma once

#include <vector>

#include "mesh/branch_chains.h"
#include "mesh/tree_mesh.h"

namespace ramus::mesh {

// Per-node and per-chain wind data shared by bark and leaves (see MeshPart::wind).
struct WindField {
  double base_z = 0, height = 0;
  std::vector<float> node_branch;  // branch-bend weight at each node
  std::vector<float> chain_phase;  // phase of each chain
  float main_bend(double z) const;
};
WindField make_wind_field(const Skeleton& s, const PreparedSkeleton& p);

// The wind skin's joints along the chains and each node's binding (wind_rig.h).
WindRig make_wind_rig(const Skeleton& s, const PreparedSkeleton& p, const WindField& wind,
                      const WindRigOptions& options);

struct TubeParams {
  int max_segments = 12;
  int min_segments = 3;
  bool caps = true;
  bool count_repairs = true;  // only LOD0 counts into the report
};

// Appends the generalized cylinder of chain `id` to `out`. Returns false (and adds nothing) when
// the chain has zero length.
bool add_chain_tube(const Skeleton& s, const PreparedSkeleton& p, std::uint32_t id,
                    const WindField& wind, const TubeParams& params, MeshPart& out,
                    MeshReport& report);

// Appends the cards of organ `i`, scaled by `extra_scale` (LODs thin leaves and enlarge the rest).
// Returns false for organs of zero or negative size.
bool add_organ_cards(const Skeleton& s, const PreparedSkeleton& p, std::size_t i,
                     const WindField& wind, const MeshOptions& options, double extra_scale,
                     MeshPart& out);

// Appends polygon organ `i` (its `vertices`), triangulated in its best-fit plane with a front
// and a back face. Returns false when the outline has no area.
bool add_organ_polygon(const Skeleton& s, const PreparedSkeleton& p, std::size_t i,
                       const WindField& wind, MeshPart& out);

}  // namespace ramus::mesh
