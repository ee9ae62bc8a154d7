// The posed mesh the preview draws: every piece skinned with its tree's pose; at every joint the
// child's root-rim vertices sit on the parent's leaf-rim vertices (no gap shows in the picture),
// in the rest pose and in random poses, at every level of detail.
#include "backends/pieces/foliage.h"
#include "backends/pieces/output_layout.h"
#include "backends/pieces/output_posed_mesh.h"
#include "backends/preview/preview.h"
#include "tests/pieces/output_fixture.h"

using namespace ramus;
using namespace ramus::pieces;
using namespace output_test;

namespace {

// Largest distance from a child's root-rim vertex to the nearest vertex of the parent's leaf
// rim it hangs from, over the whole posed mesh.
double worst_rim_gap(const PieceSet& set, const Forest& f, const mesh::TreeMesh& m,
                     std::size_t lod) {
  double worst = 0;
  std::size_t base = 0;
  for (const Tree& tree : f.trees) {
    std::vector<std::size_t> first(tree.pieces.size());
    for (std::size_t i = 0; i < tree.pieces.size(); ++i) {
      first[i] = base;
      base += set.types[tree.pieces[i].type].lods[lod].positions.size();
    }
    for (std::size_t i = 0; i < tree.pieces.size(); ++i) {
      const PlacedPiece& child = tree.pieces[i];
      if (child.parent == kNone) continue;
      const PlacedPiece& parent = tree.pieces[child.parent];
      const auto& child_rim = set.types[child.type].lods[lod].rim_loops.at(0);
      const auto& parent_rim = set.types[parent.type].lods[lod].rim_loops.at(1 + child.parent_leaf);
      REQUIRE(child_rim.size() == parent_rim.size());
      for (std::uint32_t cv : child_rim) {
        double nearest = 1e300;
        for (std::uint32_t pv : parent_rim) {
          nearest = std::min(nearest, double(distance(m.bark.positions[first[i] + cv],
                                                      m.bark.positions[first[child.parent] + pv])));
        }
        worst = std::max(worst, nearest);
      }
    }
  }
  REQUIRE(base == m.bark.positions.size());
  return worst;
}

}  // namespace

TEST_CASE("the posed mesh has no gaps at joints in any pose or level of detail",
          "[pieces][preview]") {
  const PieceSet set = lower_set();
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const Forest f = forest(set, seed, 3);  // copy 0 in the rest pose, copies 1, 2 posed
    for (std::size_t lod = 0; lod < set.lod_segments.size(); ++lod) {
      const mesh::TreeMesh m = posed_forest_mesh(set, f, lod);
      CHECK(m.bark.triangle_count() > 0);
      // Float storage of world positions: the tolerance is float rounding at the tree's size.
      CHECK(worst_rim_gap(set, f, m, lod) < 1e-5 * set.rim_radius * 10);
    }
  }
}

TEST_CASE("the posed pieces preview renders a picture", "[pieces][preview]") {
  const PieceSet set = lower_set();
  const Forest f = forest(set, 4, 2);
  const mesh::TreeMesh m = posed_forest_mesh(set, f, 1);
  // The leaf cards of the foliage clouds, each with its back face: twice the glTF's triangles.
  const PiecesLayout layout = layout_forest(set, f);
  const LeafCards cards = leaf_cards(forest_clouds(set, f, layout), 1);
  CHECK(cards.indices.size() > 0);
  CHECK(m.leaves.triangle_count() == 2 * cards.indices.size() / 3);
  preview::PreviewOptions po;
  po.width = 240;
  po.height = 160;
  po.supersample = 1;
  const std::vector<std::uint8_t> rgb = preview::render_rgb(m, po);
  std::size_t drawn = 0;
  for (std::size_t i = 0; i + 2 < rgb.size(); i += 3) {
    if (std::abs(int(rgb[i]) - 245) > 6 || std::abs(int(rgb[i + 1]) - 245) > 6) ++drawn;
  }
  CHECK(drawn > rgb.size() / 3 / 100);
  CHECK_THROWS_AS(posed_forest_mesh(set, f, 42), PiecesError);
}
