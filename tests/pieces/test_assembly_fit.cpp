// Assembly by fitting a skeleton (section 4.2-4.3): internodes become tubes, forks Ys (asymmetric
// through bone scaling), forks of three a Psi or a chain of Ys; the rims still interlock in the
// rest pose and in random poses, and every segment's end rim sits on its skeleton node.
#include <filesystem>
#include <fstream>

#include "compiler/grow.h"
#include "test_piece_support.h"

using namespace piece_test;

namespace {

const char* kSet = R"(
pieces fitted {
  piece I = tube(length: 4, taper: 0.9);
  piece Y = fork(angle: 30);
  piece P = trifurcation(angle: 30);
  root I;
}
)";

// A trunk, a fork of two with unequal radii, one child forking in three, one in five.
Skeleton sample_skeleton() {
  Skeleton s;
  auto add = [&](Vec3 p, double r, std::uint32_t parent) {
    SkeletonNode n;
    n.position = p;
    n.radius = r;
    n.parent = parent;
    return s.add(n);
  };
  std::uint32_t root = add({0, 0, 0}, 0.3, kNoParent);
  std::uint32_t a = add({0, 0, 1.5}, 0.3, root);
  std::uint32_t b = add({0.1, 0, 3}, 0.25, a);
  std::uint32_t l = add({-1, 0.2, 4.5}, 0.2, b);     // thick
  std::uint32_t r = add({1.2, -0.1, 4.2}, 0.08, b);  // thin: an asymmetric fork
  std::uint32_t l2 = add({-1.5, 0.3, 6}, 0.15, l);
  for (int k = 0; k < 3; ++k) {
    double az = 2 * M_PI * k / 3;
    add(Vec3{-1.5, 0.3, 6} + Vec3{std::cos(az), std::sin(az), 1.2}, 0.06, l2);
  }
  std::uint32_t r2 = add({1.6, -0.2, 5}, 0.07, r);
  for (int k = 0; k < 5; ++k) {
    double az = 2 * M_PI * k / 5;
    std::uint32_t c =
        add(Vec3{1.6, -0.2, 5} + Vec3{0.6 * std::cos(az), 0.6 * std::sin(az), 0.8}, 0.03, r2);
    add(Vec3{1.6, -0.2, 5} + Vec3{0.9 * std::cos(az), 0.9 * std::sin(az), 1.6}, 0.02, c);
  }
  return s;
}

std::size_t count_kind(const PieceSet& set, const Tree& t, PieceKind k) {
  std::size_t n = 0;
  for (const PlacedPiece& p : t.pieces) n += set.types[p.type].kind == k;
  return n;
}

void check_fitted(const PieceSet& set, const Skeleton& sk, const Tree& tree) {
  RimGap rest = rim_gaps(set, tree, tree.pose);
  CHECK(rest.joints == tree.pieces.size() - 1);
  CHECK(rest.position < 1e-5);
  CHECK(rest.normal < 1e-5);
  for (std::uint64_t seed = 0; seed < 100; ++seed) {
    RimGap g = rim_gaps(set, tree, random_pose(tree, tree.pose, seed));
    REQUIRE(g.position < 1e-5);
    REQUIRE(g.normal < 1e-5);
  }
  // Every non-root node is the end of one tube: a tube's terminal joint sits on it, scaled to
  // the radius the skeleton asks for there.
  std::vector<Mat4> w = bone_world(tree, tree.pose);
  std::vector<std::pair<Vec3, double>> ends;
  for (const PlacedPiece& p : tree.pieces) {
    if (set.types[p.type].kind != PieceKind::Tube) continue;
    const Mat4& m = w[p.bone_offset + 1];
    ends.push_back({m.point({0, 0, 0}), length(m.direction({1, 0, 0}))});
  }
  std::size_t matched = 0;
  for (std::uint32_t i = 0; i < sk.size(); ++i) {
    if (sk.nodes[i].parent == kNoParent) continue;
    for (const auto& [pos, scale] : ends) {
      if (distance(pos, sk.nodes[i].position) < 1e-9) {
        ++matched;
        break;
      }
    }
  }
  CHECK(matched == sk.size() - 1);
}

}  // namespace

TEST_CASE("a skeleton becomes tubes, forks and trifurcations whose rims interlock") {
  PieceSet set = lower_text(kSet);
  Skeleton sk = sample_skeleton();
  Tree tree = fit_skeleton(set, sk, {});
  // One tube per segment; a Y at the fork of two; a Psi at the fork of three; the fork of five
  // becomes a chain: a Y, a Y, then a Psi for the last three.
  CHECK(count_kind(set, tree, PieceKind::Tube) == sk.size() - 1);
  CHECK(count_kind(set, tree, PieceKind::Trifurcation) == 2);
  CHECK(count_kind(set, tree, PieceKind::Fork) == 1 + 2);
  check_fitted(set, sk, tree);
  CHECK(tree.pose.size() == tree.bones.size());
  for (std::size_t b = 0; b < tree.bones.size(); ++b) CHECK(tree.pose[b].s == tree.bones[b].rest.s);
}

TEST_CASE("without a trifurcation a fork of three is a chain of two Ys") {
  PieceSet set = lower_text("pieces f { piece I = tube(); piece Y = fork(); root I; }");
  Skeleton sk = sample_skeleton();
  Tree tree = fit_skeleton(set, sk, {});
  CHECK(count_kind(set, tree, PieceKind::Fork) == 1 + 2 + 4);
  check_fitted(set, sk, tree);
}

TEST_CASE("an asymmetric fork comes from unequal terminal-joint scales") {
  PieceSet set = lower_text(kSet);
  Tree tree = fit_skeleton(set, sample_skeleton(), {});
  std::vector<Mat4> w = bone_world(tree, tree.pose);
  const PlacedPiece* y = nullptr;
  for (const PlacedPiece& p : tree.pieces) {
    if (set.types[p.type].kind == PieceKind::Fork) {
      y = &p;
      break;
    }
  }
  REQUIRE(y);
  double s1 = length(w[y->bone_offset + 1].direction({1, 0, 0}));
  double s2 = length(w[y->bone_offset + 2].direction({1, 0, 0}));
  CHECK(std::max(s1, s2) / std::min(s1, s2) == Approx(0.2 / 0.08));
}

TEST_CASE("fitting a skeleton grown from an lsystem in the same file") {
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / "ramus_pieces_fit";
  fs::create_directories(dir);
  fs::path file = dir / "grown.ramus";
  std::ofstream(file) << R"(
lsystem bush {
  derive 4;
  axiom !(0.3) A;
  A -> F(1) [ &(35) !(0.7) A ] /(137.5) [ &(35) !(0.7) A ] F(0.5) A;
}
pieces bark {
  piece I = tube(length: 4, taper: 0.9);
  piece Y = fork();
  root I;
}
)";
  SourceManager sm;
  DiagnosticSink diags;
  Program prog = load_program(file.string(), sm, diags);
  REQUIRE(!diags.has_errors());
  CHECK(pieces_block_fits_skeleton(prog, ""));
  PieceSet set = lower_pieces(prog, sm, {}, diags);
  REQUIRE(!diags.has_errors());
  Skeleton sk = grow_file(file.string(), {}, sm, diags);
  REQUIRE(sk.size() > 50);
  FitOptions fo;
  fo.seed = 2;
  Tree tree = fit_skeleton(set, sk, fo);
  CHECK(tree.pieces.size() > sk.size() / 2);
  RimGap g = rim_gaps(set, tree, tree.pose);
  CHECK(g.position < 1e-5);
  CHECK(g.normal < 1e-5);
  // Deterministic per seed.
  Tree again = fit_skeleton(set, sk, fo);
  REQUIRE(again.pieces.size() == tree.pieces.size());
  for (std::size_t i = 0; i < tree.pieces.size(); ++i) {
    CHECK(again.pieces[i].twist == tree.pieces[i].twist);
    CHECK(again.pieces[i].tiles == tree.pieces[i].tiles);
  }
  fs::remove_all(dir);
}

TEST_CASE("fitting explains what it needs") {
  PieceSet no_fork = lower_text("pieces f { piece I = tube(); root I; }");
  CHECK_THROWS_WITH(fit_skeleton(no_fork, sample_skeleton(), {}),
                    "fitting a skeleton needs a fork piece (Y)");
  PieceSet set = lower_text(kSet);
  CHECK_THROWS_WITH(fit_skeleton(set, Skeleton{}, {}), "the skeleton is empty");
}
