// The built-in pieces (section 4.1-4.3): canonical root rims, leaf rims on their building
// transforms, rim normals on the universal cone, joints and weights.
#include "test_piece_support.h"

using namespace piece_test;

namespace {

void check_piece(const PieceType& t) {
  INFO("piece " << t.name);
  const PieceMesh& m = t.lods[0];
  REQUIRE(m.segments == 1);
  REQUIRE(m.positions.size() == m.normals.size());
  REQUIRE(m.positions.size() == m.joints.size());
  REQUIRE(m.positions.size() == m.weights.size());
  REQUIRE(m.quads.size() == m.quad_tile_type.size());
  REQUIRE(t.joints.size() == 1 + t.leaves.size());
  // Root rim: the canonical hexagon, weight 1 on the root joint.
  for (int k = 0; k < 6; ++k) {
    std::uint32_t v = t.root.corners[k];
    double a = M_PI / 3 * k;
    CHECK(distance(m.positions[v], Vec3{std::cos(a), std::sin(a), 0}) < 1e-12);
    CHECK(m.weights[v][0] == 1.0f);
    CHECK(m.joints[v][0] == 0);
    // The cone normal: outward, tilted by the universal slope.
    CHECK(std::abs(m.normals[v].z / std::hypot(m.normals[v].x, m.normals[v].y) - kRimConeSlope) <
          1e-12);
  }
  // Leaf rims: building transform of the canonical corners, normals rotated alike, weight 1 on
  // their terminal joint; the joint's bind pose is the building transform.
  for (std::size_t r = 0; r < t.leaves.size(); ++r) {
    const Rim& rim = t.leaves[r];
    CHECK(rim.joint == r + 1);
    CHECK(t.joints[rim.joint].name == "rim:" + rim.name);
    Mat4 id = t.joints[rim.joint].bind * t.joints[rim.joint].inverse_bind;
    for (int e = 0; e < 16; ++e) CHECK(std::abs(id.m[e] - Mat4{}.m[e]) < 1e-12);
    for (int k = 0; k < 6; ++k) {
      double a = M_PI / 3 * k;
      std::uint32_t v = rim.corners[k];
      Vec3 want = rim.building.point({std::cos(a), std::sin(a), 0});
      CHECK(distance(m.positions[v], want) < 1e-12);
      Vec3 n = rim.building.r.rotate(normalized(Vec3{std::cos(a), std::sin(a), kRimConeSlope}));
      CHECK(distance(m.normals[v], n) < 1e-12);
      CHECK(m.weights[v][0] == 1.0f);
      CHECK(m.joints[v][0] == rim.joint);
    }
  }
  // Weights: at most 4, non-negative, summing to 1, naming existing joints.
  for (std::size_t v = 0; v < m.weights.size(); ++v) {
    double sum = 0;
    for (int k = 0; k < 4; ++k) {
      CHECK(m.weights[v][k] >= 0);
      CHECK(m.joints[v][k] < t.joints.size());
      sum += m.weights[v][k];
    }
    CHECK(std::abs(sum - 1) < 1e-6);
    CHECK(std::abs(length(m.normals[v]) - 1) < 1e-9);
  }
  // Quads face outwards: the quad normal points away from the piece's axis region, measured
  // as agreeing with its corners' vertex normals.
  for (const auto& q : m.quads) {
    Vec3 n = cross(m.positions[q[2]] - m.positions[q[0]], m.positions[q[3]] - m.positions[q[1]]);
    double agree = 0;
    for (std::uint32_t v : q) agree += dot(n, m.normals[v]);
    CHECK(agree > 0);
  }
}

}  // namespace

TEST_CASE("built-in pieces have canonical root rims and leaf rims on their building transforms") {
  PieceSet set = lower_text(kAlmond);
  REQUIRE(set.types.size() == 5);
  CHECK(set.rim_radius == 0.2);
  for (const PieceType& t : set.types) check_piece(t);
  CHECK(set.types[0].leaves.size() == 1);
  CHECK(set.types[0].leaves[0].name == "top");
  CHECK(set.types[1].leaves.size() == 2);
  CHECK(set.types[2].leaves.size() == 3);
  CHECK(set.types[2].leaves[1].name == "middle");
  CHECK(set.types[4].leaves[1].name == "branch");
}

TEST_CASE("the tube narrows slightly and the fork is symmetric") {
  PieceSet set = lower_text(kAlmond);
  const PieceType& I = set.types[0];
  CHECK(I.leaves[0].building.s == Approx(0.85));
  CHECK(I.leaves[0].building.t.z == Approx(4));
  CHECK(std::abs(I.leaves[0].building.t.x) < 1e-12);
  const PieceType& Y = set.types[1];
  // The two stems are co-dominant: equal scales, mirror images through the fork's axis.
  Trs l = Y.leaves[0].building, r = Y.leaves[1].building;
  CHECK(l.s == Approx(r.s));
  CHECK(l.t.z == Approx(r.t.z));
  CHECK(l.t.y == Approx(-r.t.y));
  CHECK(l.t.y > 0.5);
  // Every corner of the left rim has the right rim's corner three steps on, turned 180 degrees.
  for (int k = 0; k < 6; ++k) {
    Vec3 a = Y.lods[0].positions[Y.leaves[0].corners[k]];
    Vec3 b = Y.lods[0].positions[Y.leaves[1].corners[k]];
    CHECK(std::abs(a.z - b.z) < 1e-9);
  }
}

TEST_CASE("a planar trifurcation keeps its stems in one plane, a 3D one does not") {
  PieceSet set = lower_text(kAlmond);
  const PieceType& planar = set.types[3];
  const PieceType& spatial = set.types[2];
  // The planar one's stem axes all lie in the plane spanned by z and azimuth 30 degrees.
  Vec3 plane_normal{-std::sin(M_PI / 6), std::cos(M_PI / 6), 0};
  for (const Rim& r : planar.leaves) {
    CHECK(std::abs(dot(r.building.r.rotate({0, 0, 1}), plane_normal)) < 1e-9);
  }
  double off_plane = 0;
  for (const Rim& r : spatial.leaves) {
    off_plane = std::max(off_plane, std::abs(dot(r.building.r.rotate({0, 0, 1}), plane_normal)));
  }
  CHECK(off_plane > 0.2);
  // The middle stem of the planar one goes straight up.
  Vec3 axis = planar.leaves[1].building.r.rotate({0, 0, 1});
  CHECK(axis.z == Approx(1).margin(1e-9));
}

TEST_CASE("tile types: tubes take type 1 only, forks type 2 near the fork") {
  PieceSet set = lower_text(kAlmond);
  for (std::uint8_t t : set.types[0].lods[0].quad_tile_type) CHECK(t == 1);
  for (std::size_t p = 1; p < set.types.size(); ++p) {
    const auto& tt = set.types[p].lods[0].quad_tile_type;
    std::size_t twos = std::count(tt.begin(), tt.end(), 2);
    CHECK(twos > 0);
    CHECK(twos < tt.size() / 2);
    // Quads at the rims are far from the fork: type 1.
    const PieceMesh& m = set.types[p].lods[0];
    for (std::size_t q = 0; q < m.quads.size(); ++q) {
      for (std::uint32_t v : m.quads[q]) {
        if (std::find(set.types[p].root.corners.begin(), set.types[p].root.corners.end(), v) !=
            set.types[p].root.corners.end()) {
          CHECK(int(m.quad_tile_type[q]) == 1);
        }
      }
    }
  }
}

TEST_CASE("bad piece arguments are reported at the argument") {
  SourceManager sm;
  DiagnosticSink diags;
  Program prog =
      load_program_text("bad.ramus",
                        "pieces p { piece I = tube(lenght: 2); piece J = tube(taper: -1);"
                        " rim circle(radius: 1); root I; }",
                        sm, diags);
  check_program(prog, sm, diags);
  REQUIRE(!diags.has_errors());
  lower_pieces(prog, sm, {}, diags);
  REQUIRE(diags.all().size() == 3);
  CHECK(diags.all()[0].message == "'tube' has no argument 'lenght'");
  CHECK(diags.all()[1].message == "'taper' of 'tube' must be positive");
  CHECK(diags.all()[2].message == "the universal rim is a regular hexagon, not 'circle'");
}
