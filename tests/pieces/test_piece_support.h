// Shared by the pieces unit tests: lowering a grammar given as text, and measuring how well the
// rims of an assembled, posed tree interlock.
#pragma once

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "backends/pieces/pieces.h"
#include "grammar/check.h"
#include "grammar/loader.h"

namespace piece_test {

using namespace ramus;
using namespace ramus::pieces;

inline PieceSet lower_text(const std::string& text, LowerPiecesOptions options = {}) {
  SourceManager sm;
  DiagnosticSink diags;
  Program prog = load_program_text("test.ramus", text, sm, diags);
  check_program(prog, sm, diags);
  INFO((diags.all().empty() ? std::string() : diags.all().front().message));
  REQUIRE(!diags.has_errors());
  PieceSet set = lower_pieces(prog, sm, options, diags);
  INFO((diags.all().empty() ? std::string() : diags.all().front().message));
  REQUIRE(!diags.has_errors());
  return set;
}

inline const char* kAlmond = R"(
pieces almond {
  rim hexagon(radius: 0.2);
  piece I = tube(length: 4, taper: 0.85);
  piece Y = fork(length: 3, angle: 35, taper: 0.8);
  piece P = trifurcation(angle: 30);
  piece Q = trifurcation(planar: 1);
  piece A = attachment(angle: 55);
  root I;
  I.top -> I 0.5 | Y 0.3 | P 0.1 | A 0.1;
  Y.left -> I 0.6 | Y 0.4;
  Y.right -> I 0.6 | Q 0.4;
  P.left -> I;
  P.middle -> I 2 | Y 1;
  P.right -> I;
  Q.left -> I;
  Q.middle -> Y;
  Q.right -> I;
  A.stem -> I;
  A.branch -> Y;
  twist any;
  depth 6;
}
)";

struct RimGap {
  double position = 0;  // largest vertex gap / rim radius
  double normal = 0;    // largest angle between matching normals, radians
  std::size_t joints = 0;
};

// Every joint of `tree` in the pose `locals`: the child's root-rim loop (at LOD child_lod)
// against the parent's leaf-rim loop (at LOD parent_lod), vertex for vertex. Loops at different
// tessellation levels are compared on the vertices both have (every (fine/coarse)-th one).
inline RimGap rim_gaps(const PieceSet& set, const Tree& tree, std::span<const Trs> locals,
                       std::size_t parent_lod = 0, std::size_t child_lod = 0) {
  std::vector<Mat4> world = bone_world(tree, locals);
  std::vector<SkinnedPiece> skinned_parent(tree.pieces.size()), skinned_child(tree.pieces.size());
  for (std::uint32_t i = 0; i < tree.pieces.size(); ++i) {
    skinned_parent[i] = skin_piece(set, tree, world, i, parent_lod);
    skinned_child[i] = skin_piece(set, tree, world, i, child_lod);
  }
  RimGap g;
  for (std::uint32_t i = 0; i < tree.pieces.size(); ++i) {
    const PlacedPiece& c = tree.pieces[i];
    if (c.parent == kNone) continue;
    const PlacedPiece& p = tree.pieces[c.parent];
    const PieceMesh& cm = set.types[c.type].lods[child_lod];
    const PieceMesh& pm = set.types[p.type].lods[parent_lod];
    const auto& cl = cm.rim_loops[0];
    const auto& pl = pm.rim_loops[1 + c.parent_leaf];
    const SkinnedPiece& cs = skinned_child[i];
    const SkinnedPiece& ps = skinned_parent[c.parent];
    // Rim radius in the world: centre to corner 0 of the child's root rim.
    Vec3 centre{0, 0, 0};
    for (std::uint32_t k = 0; k < 6; ++k) centre += cs.positions[cl[k * cm.segments]] / 6.0;
    double radius = distance(centre, cs.positions[cl[0]]);
    int cseg = cm.segments, pseg = pm.segments, common = std::min(cseg, pseg);
    for (int k = 0; k < 6 * common; ++k) {
      // Corner k of the child's root rim sits on corner k + twist of the parent's leaf rim.
      std::size_t ci = std::size_t(k * (cseg / common));
      std::size_t pi = (std::size_t(k * (pseg / common)) + std::size_t(c.twist) * pseg) % pl.size();
      Vec3 a = cs.positions[cl[ci]], b = ps.positions[pl[pi]];
      g.position = std::max(g.position, distance(a, b) / radius);
      double d = std::clamp(dot(cs.normals[cl[ci]], ps.normals[pl[pi]]), -1.0, 1.0);
      g.normal = std::max(g.normal, std::acos(d));
    }
    ++g.joints;
  }
  return g;
}

}  // namespace piece_test
