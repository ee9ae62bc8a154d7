// Helpers for the .rmb tests: the example grammars, lowered as `ramus build` lowers them.
#pragma once

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "compiler/derive.h"
#include "compiler/ir.h"
#include "compiler/pipeline.h"
#include "grammar/diagnostic.h"
#include "grammar/source.h"

namespace ramus::test {

// Every .ramus under examples/ that holds an lsystem block (what an .rmb carries; examples of
// pieces alone have none), sorted, relative to the source tree.
inline std::vector<std::string> example_grammars() {
  namespace fs = std::filesystem;
  std::vector<std::string> out;
  const fs::path root = fs::path(RAMUS_SOURCE_DIR);
  for (const auto& e : fs::recursive_directory_iterator(root / "examples")) {
    if (e.path().extension() != ".ramus") continue;
    std::ifstream in(e.path());
    std::stringstream text;
    text << in.rdbuf();
    // An lsystem block of its own (a line starting with it), not one named in a comment.
    const std::string t = "\n" + text.str();
    if (t.find("\nlsystem ") == std::string::npos) continue;
    out.push_back(fs::relative(e.path(), root).string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

inline ir::Grammar lower_example(const std::string& relative) {
  SourceManager sm;
  DiagnosticSink diags;
  return lower_file(std::string(RAMUS_SOURCE_DIR) + "/" + relative, GrowOptions{}, sm, diags);
}

inline ModuleString derive_steps(const ir::Grammar& g, int steps,
                                 std::uint64_t max_modules = 100'000'000) {
  DeriveOptions d;
  d.steps = steps;
  d.max_modules = max_modules;
  d.threads = 1;
  return derive(g, d);
}

// Six steps of `g` with a given seed on one thread: for checking that a grammar and its decoded
// (or decompiled) form derive the same for seeds other than the stored one.
inline ModuleString derive_with_seed(const ir::Grammar& g, std::uint64_t seed) {
  DeriveOptions d;
  d.steps = 6;
  d.seed = seed;
  d.threads = 1;
  return derive(g, d);
}

}  // namespace ramus::test
