// Gravitropism of inferred grammars (tropism_fit.h, ABOP 2.2): the elasticity of a synthetic
// skeleton bent by a known tropism is recovered, the bundled grammars' elasticities are
// recovered from their grown trees, and rules measured from the bent heading see no bend left.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/rng.h"
#include "infer/skeleton/branch_rules.h"
#include "infer/skeleton/skeleton_grammar.h"
#include "infer/skeleton/tropism_fit.h"
#include "skeleton_fixtures.h"

using namespace ramus;
using namespace ramus::skeleton_infer;
using skeleton_test::add_node;

namespace {

constexpr double kPi = 3.14159265358979323846;
const Vec3 kDown{0, 0, -1};

// Axes leaving a trunk at inclinations from 20 to 160 degrees, each internode one segment whose
// direction is its predecessor's bent by e (one turn per internode) and then turned by a random
// angle of sd `noise` degrees. Every axis node carries a 5 cm side twig, so each segment is its own
// internode.
Skeleton bent_axes(double e, double noise, std::uint64_t seed) {
  Skeleton s;
  Rng rng(seed);
  const std::uint32_t root = add_node(s, {0, 0, 0}, kNoParent, 0.3);
  std::uint32_t top = add_node(s, {0, 0, 1}, root, 0.3);
  for (int a = 0; a < 24; ++a) {
    const double incl = (20 + 140 * rng.uniform01()) * kPi / 180;
    const double az = 2 * kPi * rng.uniform01();
    Vec3 h{std::sin(incl) * std::cos(az), std::sin(incl) * std::sin(az), std::cos(incl)};
    Vec3 p = s.nodes[top].position;
    std::uint32_t at = top;
    for (int k = 0; k < 8; ++k) {
      p += h * 0.5;
      at = add_node(s, p, at, 0.05);
      // The side twig leaves at a right angle, so the next segment continues the axis.
      const Vec3 side = normalized(cross(h, Vec3{0, 0, 1}), Vec3{1, 0, 0});
      add_node(s, p + side * 0.05, at, 0.01);
      h = bend_towards(h, kDown, e, 1);
      // A random turn: about a random axis perpendicular to h.
      Vec3 r{rng.normal(), rng.normal(), rng.normal()};
      r = normalized(r - h * dot(r, h));
      const double t = rng.normal() * noise * kPi / 180;
      h = normalized(h * std::cos(t) + r * std::sin(t));
    }
    add_node(s, p + h * 0.5, at, 0.05);  // the tip: the last side twig's node forks too
    top = add_node(s, s.nodes[top].position + Vec3{0, 0, 0.3}, top, 0.3);
  }
  return s;
}

}  // namespace

TEST_CASE("tropism fit: the elasticity of a synthetic bent skeleton is recovered",
          "[skeleton_infer]") {
  for (double e : {0.05, 0.1, 0.2}) {
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
      const BranchRules rules = extract_branch_rules(bent_axes(e, 2.0, seed));
      std::vector<ElasticityFit> per;
      const ElasticityFit f = fit_elasticity(rules, 1, &per);
      INFO("e " << e << " seed " << seed << " fitted " << f.elasticity << " pairs " << f.pairs);
      CHECK(f.pairs > 100);
      CHECK(std::abs(f.elasticity - e) < 0.01 + 0.1 * e);
      CHECK(f.r2 > (e < 0.1 ? 0.2 : 0.5));
    }
  }
  // Without tropism the fit is near 0; with two turns per internode it halves.
  const BranchRules straight = extract_branch_rules(bent_axes(0, 2.0, 3));
  CHECK(std::abs(fit_elasticity(straight, 1).elasticity) < 0.01);
  const BranchRules bent = extract_branch_rules(bent_axes(0.2, 0.5, 3));
  CHECK(fit_elasticity(bent, 2).elasticity == Approx(0.1).margin(0.01));
}

TEST_CASE("tropism fit: bend_towards turns like the turtle and stops at the tropism vector",
          "[skeleton_infer]") {
  const Vec3 h{1, 0, 0};
  const Vec3 b = bend_towards(h, kDown, 0.1, 1);  // sin(90 deg) = 1: 0.1 rad down
  CHECK(std::acos(-b.z) == Approx(kPi / 2 - 0.1).margin(1e-9));
  CHECK(b.y == Approx(0).margin(1e-12));
  // Many turns hang the heading towards T, never past it.
  const Vec3 hung = bend_towards(h, kDown, 0.3, 200);
  CHECK(hung.z < -0.999);
  CHECK(bend_towards(kDown, kDown, 0.5, 3).z == Approx(-1));
}

TEST_CASE("tropism fit: rules measured from the bent heading keep only the random turn",
          "[skeleton_infer]") {
  BranchRules rules = extract_branch_rules(bent_axes(0.15, 0.0, 4));
  double before = 0, after = 0;
  std::size_t n = 0;
  auto mean_continuation_theta = [](const BranchRules& r, std::size_t& count) {
    double sum = 0;
    count = 0;
    for (const NodeRule& nr : r.rules) {
      if (nr.child_count < 2 || r.internodes[nr.internode].parent == kNone) continue;
      const ChildRule& c = *r.begin(nr);
      if (!r.internodes[c.internode].continuation) continue;
      sum += c.theta;
      ++count;
    }
    return sum / double(std::max<std::size_t>(count, 1));
  };
  before = mean_continuation_theta(rules, n);
  measure_from_bent_heading(rules, 0.15, 1);
  after = mean_continuation_theta(rules, n);
  CHECK(n > 100);
  CHECK(before > 3);    // the bend, about 0.15 rad sin(incl)
  CHECK(after < 0.01);  // nothing left without noise
  // Children stay continuation first, laterals by increasing azimuth.
  for (const NodeRule& nr : rules.rules) {
    for (const ChildRule* c = rules.begin(nr); c != rules.end(nr); ++c) {
      if (c == rules.begin(nr)) {
        CHECK(rules.internodes[c->internode].continuation);
      } else if (c != rules.begin(nr) + 1) {
        CHECK((c - 1)->phi <= c->phi);
      }
    }
  }
}

TEST_CASE("tropism fit: the bundled grammars' elasticities are recovered from their trees",
          "[skeleton_infer]") {
  // conifer 0.1, weeping 0.12, broadleaf 0.04 (their `elasticity`); every internode of these
  // grammars is one F except the collapsed twigs. Weeping's continuations also take random
  // turns, so its tolerance is wider.
  struct Case {
    const char* path;
    double e, tol;
  };
  for (const Case& c : {Case{"examples/trees/conifer.ramus", 0.1, 0.01},
                        Case{"examples/trees/weeping.ramus", 0.12, 0.03},
                        Case{"examples/trees/broadleaf.ramus", 0.04, 0.01}}) {
    for (std::uint64_t seed : {1, 2, 3}) {
      const Skeleton tree = skeleton_test::grow_example(c.path, seed);
      GrammarOptions o;
      const InferredGrammar g = infer_grammar(tree, o);
      INFO(c.path << " seed " << seed << " fitted " << g.tropism.elasticity);
      CHECK(g.tropism.elasticity == Approx(c.e).margin(c.tol));
      CHECK(g.text.find("tropism 0, 0, -1;") != std::string::npos);
      CHECK(g.text.find("elasticity ") != std::string::npos);
      std::string messages;
      CHECK(skeleton_test::grammar_checks(g.text, messages));
      // --no-tropism writes none.
      o.tropism = false;
      CHECK(infer_grammar(tree, o).text.find("elasticity") == std::string::npos);
    }
  }
}
