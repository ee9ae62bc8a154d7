// Skeleton -> L-system inference benchmark (docs/skeleton-inference.md): extraction of the
// per-node rules (Eq. 4.11) and their clustering for a large skeleton.
//   bench_skeleton_infer [NODES] [SEED]   a random tree of NODES nodes (default 100000): chains of
//                                         1-6 segments between forks of 2-3 children
// Prints the time of each stage (best of 3 runs) and the rule counts, for the clustered model and
// for the scaffold model (the default of `ramus infer --method skeleton`).
//   bench_skeleton_infer fidelity [--stations N] [--method bsg|flood] [--seeds K] [--no-tropism]
//                        INPUT...
//     the fidelity table of docs/skeleton-inference.md: per INPUT (a scan, or a grammar: its
//     seed-1 tree, or with --stations N that tree scanned from N stations around it, 5 mm range
//     noise, then reconstructed), the grammar inferred as `ramus infer --method skeleton` does,
//     K regrown trees (default 10) and the KS distances against the input skeleton (for a
//     scanned grammar: against its reconstruction, the honest input of inference, and against
//     the grammar's own K trees). Ratios are regrown mean / input mean.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "backends/scanner/scanner.h"
#include "compiler/grow.h"
#include "core/rng.h"
#include "formats/point_cloud_io.h"
#include "grammar/diagnostic.h"
#include "grammar/source.h"
#include "reconstruct/flood/flood_skeleton.h"
#include "reconstruct/reconstruct.h"
#include "infer/skeleton/branch_rules.h"
#include "infer/skeleton/fidelity.h"
#include "infer/skeleton/rule_clustering.h"
#include "infer/skeleton/scaffold_grammar.h"
#include "infer/skeleton/skeleton_grammar.h"
#include "tests/support/harness.h"

using namespace ramus;
using namespace ramus::skeleton_infer;

namespace {

// A tree grown breadth-first: every apex draws a chain of segments, then forks.
Skeleton random_tree(std::size_t nodes, std::uint64_t seed) {
  Rng rng(seed);
  Skeleton s;
  SkeletonNode root;
  root.radius = 0.3;
  s.add(root);
  struct Apex {
    std::uint32_t node;
    Vec3 dir;
    double len, radius;
  };
  std::vector<Apex> apices{{0, {0, 0, 1}, 1.0, 0.3}}, next;
  while (s.size() < nodes && !apices.empty()) {
    next.clear();
    for (const Apex& a : apices) {
      std::uint32_t n = a.node;
      const int segments = 1 + int(rng.below(6));
      for (int k = 0; k < segments && s.size() < nodes; ++k) {
        SkeletonNode c;
        c.parent = n;
        c.radius = a.radius;
        c.position = s.nodes[n].position + a.dir * (a.len / segments);
        n = s.add(c);
      }
      const int kids = 2 + int(rng.below(2));
      for (int k = 0; k < kids; ++k) {
        const Vec3 jitter{rng.normal(0, k == 0 ? 0.1 : 0.6), rng.normal(0, k == 0 ? 0.1 : 0.6),
                          rng.normal(0, 0.2)};
        next.push_back({n, normalized(a.dir + jitter), a.len * rng.uniform(0.6, 0.95),
                        a.radius * (k == 0 ? 0.8 : 0.6)});
      }
    }
    std::swap(apices, next);
  }
  return s;
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

Skeleton grow_path(const std::string& path, std::optional<std::uint64_t> seed) {
  GrowOptions o;
  o.seed = seed;
  SourceManager sm;
  DiagnosticSink diags;
  return grow_file(path, o, sm, diags);
}

Skeleton grow_text(const std::string& text, std::uint64_t seed) {
  const auto path = std::filesystem::temp_directory_path() / "bench_skeleton_fidelity.ramus";
  std::FILE* f = std::fopen(path.string().c_str(), "wb");
  std::fwrite(text.data(), 1, text.size(), f);
  std::fclose(f);
  return grow_path(path.string(), seed);
}

// The tree with the most length of the chosen reconstruction, as `ramus infer` picks it.
Skeleton reconstruct_largest(const PointCloud& cloud, const std::string& method) {
  ReconstructResult r;
  if (method == "flood") {
    r = flood::flood_reconstruct(cloud, flood::FloodOptions{});
  } else {
    ReconstructOptions o;
    o.leaves = false;
    r = reconstruct(cloud, o);
  }
  if (r.trees.empty()) throw std::runtime_error("no tree reconstructed");
  std::size_t pick = 0;
  for (std::size_t t = 1; t < r.trees.size(); ++t) {
    if (r.trees[t].total_length() > r.trees[pick].total_length()) pick = t;
  }
  return r.trees[pick];
}

void print_row(const std::string& name, const InferredGrammar& g, const Distributions& a,
               const Distributions& b) {
  const auto c = compare(a, b);
  auto get = [&](Measure m) -> const MeasureComparison& {
    return *std::find_if(c.begin(), c.end(), [&](const auto& x) { return x.measure == m; });
  };
  auto ratio = [&](Measure m) { return get(m).mean_b / std::max(get(m).mean_a, 1e-12); };
  std::printf("| %s | %zu | %zu | %.3f | %.3f | %.3f | %.3f | %.3f | %.2f | %.2f | %.2f | %.3f |\n",
              name.c_str(), g.internodes, g.alternatives, get(Measure::BranchLength).ks,
              get(Measure::BranchingAngle).ks, get(Measure::Azimuth).ks,
              get(Measure::RadiusRatio).ks, get(Measure::BranchOrder).ks,
              ratio(Measure::TotalLength), ratio(Measure::CrownExtent), ratio(Measure::Height),
              g.tropism.elasticity);
  std::fflush(stdout);
}

int fidelity(int argc, char** argv) {
  int stations = 0, seeds = 10;
  std::string method = "bsg";
  bool tropism = true;
  std::vector<std::string> inputs;
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--stations" && i + 1 < argc) {
      stations = std::atoi(argv[++i]);
    } else if (arg == "--method" && i + 1 < argc) {
      method = argv[++i];
    } else if (arg == "--seeds" && i + 1 < argc) {
      seeds = std::max(1, std::atoi(argv[++i]));
    } else if (arg == "--no-tropism") {
      tropism = false;
    } else {
      inputs.push_back(arg);
    }
  }
  std::printf(
      "| input | internodes | alternatives | KS length | KS angle | KS azimuth | KS radius ratio "
      "| KS order | total length ratio | crown extent ratio | height ratio | elasticity |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const std::string& path : inputs) {
    const std::string name = std::filesystem::path(path).filename().string();
    const bool grammar = std::filesystem::path(path).extension() == ".ramus";
    Skeleton input;
    if (grammar && stations > 0) {
      const Skeleton truth = grow_path(path, std::nullopt);  // what `ramus scan` scans
      scanner::ScanOptions so;
      so.from = scanner::stations_around(truth, stations);
      so.noise = 0.005;
      input = reconstruct_largest(scanner::scan_skeleton(truth, so).cloud, method);
    } else if (grammar) {
      input = grow_path(path, 1);  // what `ramus infer` grows (--seed 1)
    } else {
      input = reconstruct_largest(read_point_cloud(path), method);
    }
    GrammarOptions go;
    go.calibration_seeds = 4;
    go.tropism = tropism;
    const InferredGrammar g = infer_grammar(input, go);
    Distributions in, regrown;
    measure(input, in);
    for (int s = 1; s <= seeds; ++s) measure(grow_text(g.text, std::uint64_t(s)), regrown);
    if (grammar && stations > 0) {
      const std::string tag = name + ", " + std::to_string(stations) + " stations, " + method;
      print_row(tag + ": vs reconstruction", g, in, regrown);
      Distributions own;
      for (int s = 1; s <= seeds; ++s) measure(grow_path(path, std::uint64_t(s)), own);
      print_row(tag + ": vs grammar", g, own, regrown);
    } else if (grammar) {
      Distributions own;  // as `ramus compare GRAMMAR OUT`: the grammar's own seeds
      for (int s = 1; s <= seeds; ++s) measure(grow_path(path, std::uint64_t(s)), own);
      print_row(name, g, own, regrown);
    } else {
      print_row(name + " (scan, " + method + ")", g, in, regrown);
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "fidelity") == 0) return fidelity(argc, argv);
  const std::size_t nodes = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 100000;
  const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
  const Skeleton s = random_tree(nodes, seed);
  double t_extract = 1e300, t_cluster = 1e300, t_grammar = 1e300, t_scaffold = 1e300;
  BranchRules rules;
  std::vector<RuleGroup> groups;
  InferredGrammar g;
  ScaffoldGrammar sg;
  for (int run = 0; run < 3; ++run) {
    auto t = std::chrono::steady_clock::now();
    rules = extract_branch_rules(s);
    t_extract = std::min(t_extract, seconds_since(t));
    t = std::chrono::steady_clock::now();
    groups = cluster_rules(rules, ClusterOptions{});
    t_cluster = std::min(t_cluster, seconds_since(t));
    t = std::chrono::steady_clock::now();
    g = infer_grammar(rules, GrammarOptions{});
    t_grammar = std::min(t_grammar, seconds_since(t));
    t = std::chrono::steady_clock::now();
    sg = infer_scaffold_grammar(s);
    t_scaffold = std::min(t_scaffold, seconds_since(t));
  }
  std::size_t clusters = 0;
  for (const RuleGroup& x : groups) clusters += x.clusters.size();
  std::printf("skeleton: %zu nodes, %zu internodes, %zu branch nodes\n", s.size(),
              rules.internodes.size(), g.branch_nodes);
  std::printf("extract:  %.3f s\n", t_extract);
  std::printf("cluster:  %.3f s (%zu groups, %zu clusters)\n", t_cluster, groups.size(), clusters);
  std::printf(
      "grammar (extract + cluster + budget + write): %.3f s, %zu productions, %zu alternatives\n",
      t_grammar, g.productions, g.alternatives);
  std::printf("scaffold grammar (extract + scaffold + params + axiom + write): %.3f s, %zu axes, "
              "%zu shoots, %zu bytes\n",
              t_scaffold, sg.scaffold_axes, sg.buds, sg.text.size());
  return 0;
}
