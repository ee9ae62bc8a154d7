// L-rules from the wavelet progression (III-F, Eq. 1-3 in 3D): the box of a vector, exact and
// scaled, and which successor vectors fall into it, on constructed dyads and against a brute
// force over random ones.
#include <catch2/catch.hpp>

#include "core/rng.h"
#include "infer/wavelet/l_rules.h"

using namespace ramus;
using namespace ramus::wavelet;

namespace {

DyadVector vec(std::array<int, 3> a, std::array<int, 3> b) {
  DyadVector v;
  v.start = a;
  v.end = b;
  return v;
}

std::vector<std::uint32_t> brute(const SuccessorBox& box, const std::vector<DyadVector>& fine) {
  std::vector<std::uint32_t> out;
  for (std::uint32_t i = 0; i < fine.size(); ++i) {
    if (box.contains(fine[i].start) || box.contains(fine[i].end)) out.push_back(i);
  }
  return out;
}

int random_cell(Rng& rng, int level) {
  const int lo = 1 << level;
  return lo + int(rng.uniform(0, lo - 1e-9));
}

}  // namespace

TEST_CASE("Eq. 1: the offset between neighbouring dyads is 2^j", "[lrules]") {
  for (int j = 0; j < 9; ++j) CHECK(dyad_offset(j) == (std::int64_t(1) << j));
}

TEST_CASE("Eq. 2-3: the exact box is the bounding box translated by the offset", "[lrules]") {
  // Dyad 2 is [4, 8)^3; alpha = (5, 7, 4), beta = (4, 5, 6).
  const DyadVector v = vec({5, 7, 4}, {4, 5, 6});
  const SuccessorBox e = successor_box(v, 2, LRuleOffset::exact);
  CHECK(e.r1 == std::array<std::int64_t, 3>{8, 9, 8});
  CHECK(e.r2 == std::array<std::int64_t, 3>{9, 11, 10});
  // Scaled: the same region of space in dyad 3 ([8, 16)^3), cells 2c .. 2c + 1.
  const SuccessorBox s = successor_box(v, 2, LRuleOffset::scaled);
  CHECK(s.r1 == std::array<std::int64_t, 3>{8, 10, 8});
  CHECK(s.r2 == std::array<std::int64_t, 3>{11, 15, 13});
  // The box is closed: its corners are inside, one step beyond any face is outside.
  CHECK(e.contains({8, 9, 8}));
  CHECK(e.contains({9, 11, 10}));
  CHECK_FALSE(e.contains({7, 9, 8}));
  CHECK_FALSE(e.contains({9, 12, 10}));
  CHECK_FALSE(e.contains({9, 11, 11}));
}

TEST_CASE("a successor needs its start or its end inside the box", "[lrules]") {
  const std::vector<DyadVector> coarse = {vec({4, 4, 4}, {5, 4, 5})};  // dyad 2
  // Exact box: [8, 9] x [8, 8] x [8, 9].
  const std::vector<DyadVector> fine = {
      vec({8, 8, 8}, {8, 8, 7}),        // 0: start inside
      vec({12, 12, 12}, {9, 8, 9}),     // 1: end inside (a corner)
      vec({7, 8, 8}, {10, 8, 10}),      // 2: crosses the box, both ends outside
      vec({12, 12, 12}, {13, 13, 13}),  // 3: far away
      vec({9, 9, 9}, {10, 8, 8}),       // 4: both ends just outside
  };
  const std::vector<LRule> exact = l_rules(2, coarse, fine, LRuleOffset::exact);
  REQUIRE(exact.size() == 1);
  CHECK(exact[0].level == 2);
  CHECK(exact[0].predecessor == 0);
  CHECK(exact[0].successors == std::vector<std::uint32_t>{0, 1});
  // Scaled box: [8, 11] x [8, 9] x [8, 11]; vector 2 now ends inside, 4 starts inside.
  const std::vector<LRule> scaled = l_rules(2, coarse, fine, LRuleOffset::scaled);
  REQUIRE(scaled.size() == 1);
  CHECK(scaled[0].successors == std::vector<std::uint32_t>{0, 1, 2, 4});
}

TEST_CASE("exact and scaled offsets differ away from the dyad's low corner", "[lrules]") {
  // A vector at the far corner of dyad 3 ([8, 16)^3). The exact box is its bounding box moved
  // by 8, (23, 23, 22..23), in the middle of dyad 4 ([16, 32)^3); the scaled box is the same
  // region one dyad finer, dyad 4's far corner (30..31, 30..31, 28..31).
  const std::vector<DyadVector> coarse = {vec({15, 15, 15}, {15, 15, 14})};
  const std::vector<DyadVector> fine = {vec({30, 30, 30}, {31, 31, 29}),
                                        vec({22, 23, 22}, {23, 23, 23})};
  const SuccessorBox e = successor_box(coarse[0], 3, LRuleOffset::exact);
  CHECK(e.r1 == std::array<std::int64_t, 3>{23, 23, 22});
  CHECK(e.r2 == std::array<std::int64_t, 3>{23, 23, 23});
  const auto exact = l_rules(3, coarse, fine, LRuleOffset::exact);
  REQUIRE(exact.size() == 1);
  CHECK(exact[0].successors == std::vector<std::uint32_t>{1});
  const auto scaled = l_rules(3, coarse, fine, LRuleOffset::scaled);
  REQUIRE(scaled.size() == 1);
  CHECK(scaled[0].successors == std::vector<std::uint32_t>{0});
  // No successor at all: no rule.
  CHECK(l_rules(3, coarse, {vec({16, 16, 16}, {17, 16, 16})}, LRuleOffset::scaled).empty());
}

TEST_CASE("the scaled box of one cell covers exactly its eight finer cells", "[lrules]") {
  Rng rng(11);
  for (int trial = 0; trial < 200; ++trial) {
    const int j = 1 + int(rng.uniform(0, 6));
    const std::array<int, 3> c{random_cell(rng, j), random_cell(rng, j), random_cell(rng, j)};
    const SuccessorBox b = successor_box(vec(c, c), j, LRuleOffset::scaled);
    for (int k = 0; k < 3; ++k) {
      CHECK(b.r1[k] == 2 * c[k]);
      CHECK(b.r2[k] == 2 * c[k] + 1);
      // Inside dyad j + 1.
      CHECK(b.r1[k] >= (1 << (j + 1)));
      CHECK(b.r2[k] < (1 << (j + 2)));
    }
    const SuccessorBox e = successor_box(vec(c, c), j, LRuleOffset::exact);
    for (int k = 0; k < 3; ++k) CHECK(e.r1[k] - c[k] == (1 << j));
  }
}

TEST_CASE("l_rules agrees with a brute force over random dyads", "[lrules]") {
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    Rng rng(seed);
    const int j = 1 + int(rng.uniform(0, 5));
    std::vector<DyadVector> coarse, fine;
    const int nc = 1 + int(rng.uniform(0, 30)), nf = int(rng.uniform(0, 200));
    for (int i = 0; i < nc; ++i) {
      coarse.push_back(vec({random_cell(rng, j), random_cell(rng, j), random_cell(rng, j)},
                           {random_cell(rng, j), random_cell(rng, j), random_cell(rng, j)}));
    }
    for (int i = 0; i < nf; ++i) {
      fine.push_back(
          vec({random_cell(rng, j + 1), random_cell(rng, j + 1), random_cell(rng, j + 1)},
              {random_cell(rng, j + 1), random_cell(rng, j + 1), random_cell(rng, j + 1)}));
    }
    for (LRuleOffset o : {LRuleOffset::exact, LRuleOffset::scaled}) {
      std::vector<LRule> expected;
      for (std::uint32_t c = 0; c < coarse.size(); ++c) {
        std::vector<std::uint32_t> s = brute(successor_box(coarse[c], j, o), fine);
        if (!s.empty()) expected.push_back(LRule{j, c, s});
      }
      const std::vector<LRule> got = l_rules(j, coarse, fine, o);
      INFO("seed " << seed << " offset " << to_string(o));
      REQUIRE(got.size() == expected.size());
      for (std::size_t k = 0; k < got.size(); ++k) {
        CHECK(got[k].predecessor == expected[k].predecessor);
        CHECK(got[k].successors == expected[k].successors);
      }
    }
  }
}

TEST_CASE("dyad vectors run from parent to child", "[lrules]") {
  DyadTree t;
  t.level = 2;
  t.cells = {{4, 4, 4}, {4, 4, 5}, {5, 4, 5}, {4, 5, 4}};
  t.parent = {kNoParent, 0, 1, 0};
  t.leaves = {2, 1, 1, 1};
  t.root = 0;
  const std::vector<DyadVector> v = dyad_vectors(t);
  REQUIRE(v.size() == 3);
  CHECK(v[0].from == 0);
  CHECK(v[0].to == 1);
  CHECK(v[1].start == std::array<int, 3>{4, 4, 5});
  CHECK(v[1].end == std::array<int, 3>{5, 4, 5});
  CHECK(v[2].to == 3);
  CHECK(parse_l_rule_offset("exact") == LRuleOffset::exact);
  CHECK(parse_l_rule_offset("scaled") == LRuleOffset::scaled);
  CHECK_THROWS_AS(parse_l_rule_offset("literal"), std::invalid_argument);
}
