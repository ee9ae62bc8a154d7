// Growing an inferred wavelet grammar and measuring the tree it regrows, for the tests of
// test_regrown_tree.cpp and test_inferred_params.cpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "compiler/derive.h"
#include "compiler/pipeline.h"
#include "compiler/turtle.h"
#include "core/skeleton.h"
#include "grammar/diagnostic.h"
#include "grammar/source.h"

namespace ramus::wavelet::test {

// The grammar's own derivation (`derive 1` from the axiom), with -D overrides.
inline Skeleton grow_text(const std::string& text,
                          const std::vector<std::pair<std::string, double>>& defines = {}) {
  SourceManager sources;
  DiagnosticSink diagnostics;
  GrowOptions options;
  options.defines = defines;
  const ir::Grammar g = lower_text("inferred.ramus", text, options, sources, diagnostics);
  TurtleOptions t;
  t.seed = g.settings.seed;
  t.steps = g.settings.derive;
  return interpret(g, derive(g, DeriveOptions{}), t);
}

struct TreeShape {
  std::size_t roots = 0;    // nodes without a parent: one tree has one
  double length = 0;        // total segment length
  double longest = 0;       // longest internode
  double lowest = 0;        // smallest z of a node (the base is at 0)
  double widest_child = 0;  // largest radius(child) / radius(parent)
  double height = 0;        // largest z
};

inline TreeShape shape_of(const Skeleton& s) {
  TreeShape t;
  t.lowest = s.nodes.empty() ? 0 : s.nodes[0].position.z;
  for (const SkeletonNode& n : s.nodes) {
    t.lowest = std::min(t.lowest, n.position.z);
    t.height = std::max(t.height, n.position.z);
    if (n.parent == kNoParent) {
      ++t.roots;
      continue;
    }
    const SkeletonNode& p = s.nodes[n.parent];
    const Vec3 d = n.position - p.position;
    const double len = std::sqrt(dot(d, d));
    t.length += len;
    t.longest = std::max(t.longest, len);
    if (p.radius > 0) t.widest_child = std::max(t.widest_child, n.radius / p.radius);
  }
  return t;
}

}  // namespace ramus::wavelet::test
