// Assembly from attach rules (section 4.2): topological transforms computed recursively, the depth
// limit, the rules' weights, twists, the bone buffer, and determinism per seed.
#include <map>

#include "test_piece_support.h"

using namespace piece_test;

namespace {

double max_abs_diff(const Mat4& a, const Mat4& b) {
  double d = 0;
  for (int e = 0; e < 16; ++e) d = std::max(d, std::abs(a.m[e] - b.m[e]));
  return d;
}

}  // namespace

TEST_CASE("topological transform is parent's times building times twist") {
  PieceSet set = lower_text(kAlmond);
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    AssembleOptions o;
    o.seed = seed;
    Tree t = assemble(set, o);
    REQUIRE(!t.pieces.empty());
    // The root piece: the placement, scaled by the rim radius.
    CHECK(max_abs_diff(t.pieces[0].topological, Trs{{0, 0, 0}, {}, 0.2}.matrix()) < 1e-12);
    for (const PlacedPiece& p : t.pieces) {
      if (p.parent == kNone) continue;
      const PlacedPiece& pp = t.pieces[p.parent];
      Mat4 twist = Trs{{0, 0, 0}, Quat::axis_angle({0, 0, 1}, M_PI / 3 * p.twist), 1}.matrix();
      Mat4 want =
          pp.topological * set.types[pp.type].leaves[p.parent_leaf].building.matrix() * twist;
      CHECK(max_abs_diff(p.topological, want) < 1e-12);
      CHECK(p.depth == pp.depth + 1);
      CHECK(p.twist < 6);
    }
  }
}

TEST_CASE("the bone buffer: one window of joints per piece, root joints on the parent's terminal") {
  PieceSet set = lower_text(kAlmond);
  Tree t = assemble(set, {});
  std::uint32_t next = 0;
  for (std::uint32_t i = 0; i < t.pieces.size(); ++i) {
    const PlacedPiece& p = t.pieces[i];
    CHECK(p.bone_offset == next);
    next += std::uint32_t(set.types[p.type].joints.size());
    const Bone& root = t.bones[p.bone_offset];
    CHECK(root.piece == i);
    CHECK(root.joint == 0);
    if (p.parent != kNone) {
      const PlacedPiece& pp = t.pieces[p.parent];
      CHECK(root.parent == pp.bone_offset + 1 + p.parent_leaf);
      CHECK(root.rest.t == Vec3{0, 0, 0});
      CHECK(root.rest.s == 1.0);
    }
  }
  CHECK(next == t.bones.size());
  for (std::size_t b = 0; b < t.bones.size(); ++b) {
    if (t.bones[b].parent != kNone) CHECK(t.bones[b].parent < b);
  }
  // In the rest pose every bone's world frame times its inverse bind matrix is the piece's
  // topological transform.
  std::vector<Mat4> w = bone_world(t, t.pose);
  for (const PlacedPiece& p : t.pieces) {
    const PieceType& pt = set.types[p.type];
    for (std::size_t j = 0; j < pt.joints.size(); ++j) {
      CHECK(max_abs_diff(w[p.bone_offset + j] * pt.joints[j].inverse_bind, p.topological) < 1e-9);
    }
  }
}

TEST_CASE("depth limit, piece limit and open rims") {
  PieceSet set = lower_text(kAlmond);
  for (std::uint64_t seed = 0; seed < 10; ++seed) {
    AssembleOptions o;
    o.seed = seed;
    Tree t = assemble(set, o);
    std::uint32_t deepest = 0;
    for (const PlacedPiece& p : t.pieces) deepest = std::max(deepest, p.depth);
    CHECK(deepest == 6);  // every rule has targets, so growth stops only at the limit
  }
  AssembleOptions small;
  small.max_pieces = 7;
  CHECK(assemble(set, small).pieces.size() == 7);
  CHECK(assemble(set, small).pose.size() == assemble(set, small).bones.size());

  PieceSet chain = lower_text("pieces c { piece I = tube(); root I; I.top -> I; depth 0; }");
  CHECK(assemble(chain, {}).pieces.size() == 1);
  chain.depth = 4;
  CHECK(assemble(chain, {}).pieces.size() == 5);
  // A rim without a rule stays open.
  PieceSet open =
      lower_text("pieces o { piece Y = fork(); piece I = tube(); root Y; Y.left -> I; }");
  Tree t = assemble(open, {});
  REQUIRE(t.pieces.size() == 2);
  CHECK(t.pieces[1].parent_leaf == 0);
}

TEST_CASE("weights: targets are drawn in proportion") {
  PieceSet set = lower_text(
      "pieces w { piece I = tube(); piece J = tube(taper: 0.9); root I;"
      " I.top -> I 3 | J 1; J.top -> I 3 | J 1; depth 60; }");
  std::map<std::uint32_t, int> count;
  int total = 0;
  for (std::uint64_t seed = 0; seed < 40; ++seed) {
    AssembleOptions o;
    o.seed = seed;
    Tree t = assemble(set, o);
    for (std::size_t i = 1; i < t.pieces.size(); ++i) {
      ++count[t.pieces[i].type];
      ++total;
    }
  }
  CHECK(total == 40 * 60);
  double share = double(count[0]) / total;
  CHECK(share > 0.72);
  CHECK(share < 0.78);
}

TEST_CASE("twist any draws all six twists, a fixed twist gives one") {
  PieceSet set =
      lower_text("pieces t { piece I = tube(); root I; I.top -> I; depth 200; twist any; }");
  Tree t = assemble(set, {});
  std::array<int, 6> seen{};
  for (std::size_t i = 1; i < t.pieces.size(); ++i) ++seen[t.pieces[i].twist];
  for (int k = 0; k < 6; ++k) CHECK(seen[k] > 15);
  PieceSet fixed =
      lower_text("pieces t { piece I = tube(); root I; I.top -> I; depth 20; twist 4; }");
  Tree f = assemble(fixed, {});
  for (std::size_t i = 1; i < f.pieces.size(); ++i) CHECK(int(f.pieces[i].twist) == 4);
}

TEST_CASE("assembly is deterministic per seed and differs between seeds") {
  PieceSet set = lower_text(kAlmond);
  auto signature = [&](std::uint64_t seed) {
    AssembleOptions o;
    o.seed = seed;
    Tree t = assemble(set, o);
    std::vector<double> s;
    for (const PlacedPiece& p : t.pieces) {
      s.push_back(p.type);
      s.push_back(p.twist);
      s.insert(s.end(), p.topological.m.begin(), p.topological.m.end());
      s.insert(s.end(), p.tiles.begin(), p.tiles.end());
    }
    return s;
  };
  for (std::uint64_t seed = 0; seed < 10; ++seed) CHECK(signature(seed) == signature(seed));
  CHECK(signature(1) != signature(2));
}

TEST_CASE("lowering folds constants and params and resolves rules") {
  LowerPiecesOptions o;
  o.defines = {{"deep", 3}};
  PieceSet set = lower_text(
      "const len = 2 * 3; param deep = 9;\n"
      "pieces k { piece I = tube(length: len, taper: 0.5 + 0.25); piece Y = fork(len / 2, 40);\n"
      "  root Y; Y.right -> I 2 | Y; depth deep; twist 2; }",
      o);
  REQUIRE(set.types.size() == 2);
  CHECK(set.types[0].leaves[0].building.t.z == Approx(6));
  CHECK(set.types[0].leaves[0].building.s == Approx(0.75));
  CHECK(set.root == 1);
  CHECK(set.depth == 3);
  CHECK(!set.twist_any);
  CHECK(set.twist == 2);
  REQUIRE(set.rules.size() == 1);
  CHECK(set.rules[0].piece == 1);
  CHECK(set.rules[0].leaf == 1);
  REQUIRE(set.rules[0].targets.size() == 2);
  CHECK(set.rules[0].targets[0].weight == 2);
  CHECK(set.rules[0].targets[1].weight == 1);
  CHECK(set.rule(1, 0) == nullptr);
  CHECK(set.lod_segments == std::vector<int>{1, 2, 4});
  for (const PieceType& t : set.types) CHECK(t.lods.size() == 3);
}
