// infer_wavelet_grammar (III-A to III-G): the grammar it writes checks without a diagnostic, is
// already in `ramus fmt` layout, derives into a tree of the scan's size, is deterministic, and
// bad input gets a clear error.
#include <catch2/catch.hpp>

#include "compiler/pipeline.h"
#include "compiler/turtle.h"
#include "formats/rmb/rmb_codec.h"
#include "fractal_cloud.h"
#include "grammar/format.h"
#include "grammar/parser.h"
#include "infer/wavelet/infer_grammar.h"

using namespace ramus;
using namespace ramus::wavelet;

namespace {

struct Grown {
  ir::Grammar grammar;
  Skeleton axiom, derived;
};

Grown grow(const std::string& text) {
  SourceManager sm;
  DiagnosticSink diags;
  Grown g{lower_text("inferred.ramus", text, {}, sm, diags), {}, {}};
  INFO(render_text(sm, diags.all()));
  CHECK(diags.all().empty());  // no error and no warning
  for (int steps : {0, 1}) {
    DeriveOptions d;
    d.steps = steps;
    TurtleOptions t;
    t.steps = steps;
    (steps == 0 ? g.axiom : g.derived) = interpret(g.grammar, derive(g.grammar, d), t);
  }
  return g;
}

double height(const Skeleton& s) {
  Vec3 lo, hi;
  s.bounds(lo, hi);
  return hi.z - lo.z;
}

std::string formatted(const std::string& text) {
  SourceManager sm;
  DiagnosticSink sink;
  const std::uint32_t id = sm.add("x.ramus", text);
  return format_file(parse(sm, id, sink), sm);
}

}  // namespace

TEST_CASE("infer on a synthetic fractal tree writes a grammar that checks and regrows the tree",
          "[infer]") {
  const AlignedCloud cloud = test::fractal_tree_cloud(3);
  for (int grid : {32, 64}) {
    WaveletInferOptions o;
    o.grid = grid;
    const WaveletInference r = infer_wavelet_grammar(cloud, o);
    INFO("grid " << grid);
    CHECK(r.points == cloud.points.size());
    CHECK(r.grid_side == std::size_t(grid));
    CHECK(r.voxel_rules > 0);
    CHECK(r.l_rules > 0);
    CHECK(r.productions > 0);
    CHECK(r.productions <= r.l_rules);
    CHECK(r.axiom_vectors > 10);
    CHECK(r.vectors_per_dyad.size() == std::size_t(std::log2(grid)));
    CHECK(r.timings.size() == 7);
    CHECK(r.compression.lossless_ratio > 0.5);
    CHECK(r.ramus_text.find("select nearest(sin(e) * sin(a), sin(e) * cos(a), cos(e), l / s);") !=
          std::string::npos);
    CHECK(formatted(r.ramus_text) == r.ramus_text);

    const Grown g = grow(r.ramus_text);
    CHECK(g.grammar.selection == ir::Selection::Nearest);
    // The axiom's tree is rooted at the trunk's foot (tree_hierarchy.h), at the height of the
    // scan's lowest point (the origin): one node per vector plus the root, and no other root.
    std::size_t roots = 0;
    for (const SkeletonNode& n : g.axiom.nodes) {
      if (n.parent != kNoParent) continue;
      ++roots;
      CHECK(std::abs(n.position.z) < 1e-6);
      CHECK(length(n.position) < 0.05);  // the fractal's trunk stands on the origin
    }
    CHECK(roots == 1);
    CHECK(g.axiom.size() == r.axiom_vectors + 1);
    CHECK(g.axiom.validate().empty());
    CHECK(g.derived.validate().empty());
    CHECK(g.derived.size() > g.axiom.size());  // the L-rules refine every vector
    // The cloud is about 2.4 m tall. Both the axiom (tree L-2) and the regrown tree (tree L-1)
    // start at the base and keep the coarser dyads' nodes where the finer dyad has no
    // significant cell (the straight trunk), so they span the height, never more.
    double top = 0;
    for (const Vec3& p : cloud.points) top = std::max(top, p.z);
    INFO("cloud height " << top << ", axiom " << height(g.axiom) << ", derived "
                         << height(g.derived));
    CHECK(height(g.axiom) > 0.8 * top);
    CHECK(height(g.axiom) < 1.2 * top);
    CHECK(height(g.derived) > 0.8 * top);
    CHECK(height(g.derived) < 1.2 * top);
  }
}

TEST_CASE("infer is deterministic and both offsets give valid grammars", "[infer]") {
  const AlignedCloud cloud = test::fractal_tree_cloud(5);
  WaveletInferOptions o;
  o.grid = 32;
  const WaveletInference a = infer_wavelet_grammar(cloud, o);
  const WaveletInference b = infer_wavelet_grammar(cloud, o);
  CHECK(a.ramus_text == b.ramus_text);
  o.offset = LRuleOffset::exact;
  const WaveletInference e = infer_wavelet_grammar(cloud, o);
  CHECK(e.ramus_text.find("offset exact") != std::string::npos);
  CHECK(e.ramus_text != a.ramus_text);
  grow(e.ramus_text);
  o.axiom_level = 2;
  const WaveletInference low = infer_wavelet_grammar(cloud, o);
  CHECK(low.axiom_level == 2);
  grow(low.ramus_text);
}

TEST_CASE("an inferred grammar survives the binary format with identical derivations", "[infer]") {
  WaveletInferOptions o;
  o.grid = 32;
  const WaveletInference r = infer_wavelet_grammar(test::fractal_tree_cloud(9), o);
  const Grown g = grow(r.ramus_text);
  const ir::Grammar back = decode_rmb(encode_rmb(g.grammar));
  CHECK(ir::dump(back) == ir::dump(g.grammar));
  DeriveOptions d;
  d.steps = 2;
  CHECK(to_text(back, derive(back, d)) == to_text(g.grammar, derive(g.grammar, d)));
}

TEST_CASE("infer rejects bad options and degenerate scans with clear errors", "[infer]") {
  const AlignedCloud cloud = test::fractal_tree_cloud(1, 4, 100);
  auto message = [&](const AlignedCloud& c, WaveletInferOptions o) {
    try {
      infer_wavelet_grammar(c, o);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  WaveletInferOptions o;
  o.grid = 100;
  CHECK(message(cloud, o).find("--grid") != std::string::npos);
  o.grid = 2;
  CHECK(message(cloud, o).find("from 4 to 256") != std::string::npos);
  o.grid = 512;
  CHECK(message(cloud, o).find("from 4 to 256") != std::string::npos);
  o.grid = 64;
  o.axiom_level = 6;
  CHECK(message(cloud, o).find("--axiom-level") != std::string::npos);
  o.axiom_level = -1;
  CHECK(message(cloud, o).find("--axiom-level") != std::string::npos);
  CHECK_THROWS_AS(validate_options(o), std::invalid_argument);

  // An empty cloud, a single point, and many points at one place: no tree to infer from
  // (tree_presence.h names what is missing).
  CHECK(message(AlignedCloud{}, {}).find("no points") != std::string::npos);
  AlignedCloud one;
  one.points.push_back(Vec3(0, 0, 0));
  CHECK(message(one, {}).find("the scan has 1 point(s)") != std::string::npos);
  AlignedCloud same;
  for (int i = 0; i < 1000; ++i) same.points.push_back(Vec3(1, 2, 3));
  CHECK(message(same, {}).find("no height") != std::string::npos);

  // Fewer points than voxels (40 points on a 64^3 grid) still make a grammar.
  AlignedCloud sparse;
  for (int i = 0; i < 40; ++i) {
    sparse.points.push_back(Vec3(0.1 * (i % 5), 0.07 * (i % 3), 0.25 * i));
  }
  const WaveletInference r = infer_wavelet_grammar(sparse, {});
  CHECK(r.occupied_voxels <= 40);
  grow(r.ramus_text);
}
