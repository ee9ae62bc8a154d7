// Skeleton and skinning (section 4.3), the invariants: in the rest pose and in 100 random
// poses every child's root-rim vertices coincide with the parent's leaf-rim vertices (gap below
// 1e-5 of the rim radius), and so do their normals; weights sum to 1 with at most four joints.
#include "test_piece_support.h"

using namespace piece_test;

TEST_CASE("rims coincide in the rest pose and in 100 random poses") {
  PieceSet set = lower_text(kAlmond);
  AssembleOptions o;
  o.seed = 11;
  Tree tree = assemble(set, o);
  REQUIRE(tree.pieces.size() > 20);
  RimGap rest = rim_gaps(set, tree, tree.pose);
  CHECK(rest.joints == tree.pieces.size() - 1);
  CHECK(rest.position < 1e-5);
  CHECK(rest.normal < 1e-5);
  double worst_pos = 0, worst_normal = 0, moved = 0;
  std::vector<Mat4> rest_world = bone_world(tree, tree.pose);
  for (std::uint64_t seed = 0; seed < 100; ++seed) {
    std::vector<Trs> pose = random_pose(tree, tree.pose, seed, 15);
    RimGap g = rim_gaps(set, tree, pose);
    worst_pos = std::max(worst_pos, g.position);
    worst_normal = std::max(worst_normal, g.normal);
    // The pose really moves the tree: the last piece's root bone leaves its rest place.
    std::vector<Mat4> w = bone_world(tree, pose);
    Vec3 a = w.back().point({0, 0, 0}), b = rest_world.back().point({0, 0, 0});
    moved = std::max(moved, distance(a, b));
  }
  CHECK(worst_pos < 1e-5);
  CHECK(worst_normal < 1e-5);
  CHECK(moved > 0.05);
}

TEST_CASE("random poses keep root joints rigid and are deterministic per seed") {
  PieceSet set = lower_text(kAlmond);
  Tree tree = assemble(set, {});
  std::vector<Trs> a = random_pose(tree, tree.pose, 5), b = random_pose(tree, tree.pose, 5);
  std::vector<Trs> c = random_pose(tree, tree.pose, 6);
  bool differs = false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    CHECK(a[i].r.w == b[i].r.w);
    CHECK(a[i].r.x == b[i].r.x);
    if (tree.bones[i].joint == 0) {
      CHECK(a[i].r.w == tree.pose[i].r.w);
      CHECK(a[i].r.z == tree.pose[i].r.z);
    } else {
      differs = differs || a[i].r.x != c[i].r.x;
    }
  }
  CHECK(differs);
}

TEST_CASE("skinning weights: at most four joints summing to one at every LOD") {
  PieceSet set = lower_text(kAlmond);
  for (const PieceType& t : set.types) {
    for (const PieceMesh& m : t.lods) {
      for (std::size_t v = 0; v < m.weights.size(); ++v) {
        double sum = 0;
        for (int k = 0; k < 4; ++k) {
          REQUIRE(m.weights[v][k] >= 0);
          if (m.weights[v][k] == 0) CHECK(m.joints[v][k] == 0);
          sum += m.weights[v][k];
        }
        CHECK(std::abs(sum - 1) < 1e-6);
      }
    }
  }
}

TEST_CASE("skinning in the rest pose is the topological transform of the piece") {
  PieceSet set = lower_text(kAlmond);
  Tree tree = assemble(set, {});
  std::vector<Mat4> w = bone_world(tree, tree.pose);
  for (std::uint32_t i = 0; i < tree.pieces.size(); ++i) {
    SkinnedPiece s = skin_piece(set, tree, w, i);
    const PieceMesh& m = set.types[tree.pieces[i].type].lods[0];
    for (std::size_t v = 0; v < m.positions.size(); ++v) {
      CHECK(distance(s.positions[v], tree.pieces[i].topological.point(m.positions[v])) < 1e-6);
    }
  }
}

TEST_CASE("the wind clip loops, sways terminal joints only and keeps rims closed") {
  PieceSet set = lower_text(kAlmond);
  Tree tree = assemble(set, {});
  WindOptions wo;
  wo.seed = 3;
  WindClip clip = wind_clip(tree, tree.pose, wo);
  REQUIRE(clip.times.size() == 9);
  REQUIRE(clip.rotations.size() == 9);
  CHECK(clip.times.front() == 0);
  CHECK(clip.times.back() == Approx(4));
  for (std::size_t b = 0; b < tree.bones.size(); ++b) {
    CHECK(clip.rotations.back()[b].w == clip.rotations.front()[b].w);
    if (tree.bones[b].joint == 0) {
      for (const auto& key : clip.rotations) CHECK(key[b].w == tree.pose[b].r.w);
    }
  }
  double sway = 0;
  for (std::size_t k = 0; k < clip.times.size(); ++k) {
    std::vector<Trs> pose = tree.pose;
    for (std::size_t b = 0; b < pose.size(); ++b) pose[b].r = clip.rotations[k][b];
    RimGap g = rim_gaps(set, tree, pose);
    CHECK(g.position < 1e-5);
    CHECK(g.normal < 1e-5);
    for (std::size_t b = 0; b < pose.size(); ++b) {
      double d = std::abs(pose[b].r.w * tree.pose[b].r.w + pose[b].r.x * tree.pose[b].r.x +
                          pose[b].r.y * tree.pose[b].r.y + pose[b].r.z * tree.pose[b].r.z);
      sway = std::max(sway, 2 * std::acos(std::min(1.0, d)));
    }
  }
  CHECK(sway > 2 * M_PI / 180);
  CHECK(sway < 6.01 * M_PI / 180);
}

TEST_CASE("pose copies share the topology and differ in pose and tiles") {
  PieceSet set = lower_text(kAlmond);
  Tree tree = assemble(set, {});
  Forest f = pose_copies(set, tree, 4, 9, 10.0);
  REQUIRE(f.trees.size() == 4);
  for (const Tree& t : f.trees) {
    REQUIRE(t.pieces.size() == tree.pieces.size());
    RimGap g = rim_gaps(set, t, t.pose);
    CHECK(g.position < 1e-5);
  }
  CHECK(f.trees[2].pose[0].t.x == Approx(20));
  CHECK(f.trees[1].pieces[3].tiles != f.trees[2].pieces[3].tiles);
  CHECK(f.trees[1].pose[1].r.x != f.trees[2].pose[1].r.x);
}
