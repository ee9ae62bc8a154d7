// Helpers of the skeleton-inference tests: hand-made skeletons, growing grammar text, temp files.
#pragma once

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "compiler/grow.h"
#include "compiler/pipeline.h"
#include "core/skeleton.h"
#include "grammar/diagnostic.h"
#include "grammar/format.h"
#include "grammar/parser.h"
#include "grammar/source.h"
#include "infer/skeleton/fidelity.h"

namespace skeleton_test {

using namespace ramus;

inline std::uint32_t add_node(Skeleton& s, Vec3 p, std::uint32_t parent, double r = 0.1) {
  SkeletonNode n;
  n.position = p;
  n.parent = parent;
  n.radius = r;
  return s.add(n);
}

// A scratch folder of this test binary.
inline std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "ramus_skeleton_infer_tests";
  std::filesystem::create_directories(dir);
  return dir / name;
}

inline std::string write_temp(const std::string& name, const std::string& text) {
  const auto p = scratch(name);
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

// Grows grammar text (written to a scratch file) with the given seed.
inline Skeleton grow_text(const std::string& name, const std::string& text, std::uint64_t seed) {
  const std::string path = write_temp(name, text);
  GrowOptions o;
  o.seed = seed;
  SourceManager sm;
  DiagnosticSink diags;
  return grow_file(path, o, sm, diags);
}

// Grows a grammar of the source tree (path relative to it) with `seed`, by default the
// grammar's own.
inline Skeleton grow_example(const std::string& relative,
                             std::optional<std::uint64_t> seed = std::nullopt) {
  GrowOptions o;
  o.seed = seed;
  SourceManager sm;
  DiagnosticSink diags;
  return grow_file(std::string(RAMUS_SOURCE_DIR) + "/" + relative, o, sm, diags);
}

// True when the text checks and lowers without errors.
inline bool grammar_checks(const std::string& text, std::string& messages) {
  SourceManager sm;
  DiagnosticSink diags;
  try {
    lower_text("inferred.ramus", text, GrowOptions{}, sm, diags);
  } catch (const GrowError& e) {
    messages = e.what();
    return false;
  }
  messages.clear();
  return !diags.has_errors();
}

// What `ramus fmt` would write for `text`.
inline std::string formatted(const std::string& text) {
  SourceManager sm;
  DiagnosticSink diags;
  const ast::File f = parse(sm, sm.add("x.ramus", text), diags);
  return format_file(f, sm);
}

// KS distances between the input tree and trees regrown from its grammar over `seeds` seeds.
inline std::vector<skeleton_infer::MeasureComparison> regrow_and_compare(const Skeleton& input,
                                                                         const std::string& text,
                                                                         const std::string& name,
                                                                         int seeds) {
  skeleton_infer::Distributions a, b;
  skeleton_infer::measure(input, a);
  for (int s = 1; s <= seeds; ++s)
    skeleton_infer::measure(grow_text(name, text, std::uint64_t(s)), b);
  return skeleton_infer::compare(a, b);
}

// The comparison of measure `m` in `c`, and its ratio of means (B over A).
inline const skeleton_infer::MeasureComparison& of(
    const std::vector<skeleton_infer::MeasureComparison>& c, skeleton_infer::Measure m) {
  for (const auto& x : c) {
    if (x.measure == m) return x;
  }
  FAIL("measure missing");
  return c.front();
}
inline double ratio(const skeleton_infer::MeasureComparison& m) { return m.mean_b / m.mean_a; }

}  // namespace skeleton_test
