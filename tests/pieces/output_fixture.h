// What the output tests of the pieces back end share: a small piece set lowered from grammar
// text, assembled forests of it, a scratch folder and the Khronos glTF-Validator runner.
#pragma once

#include <array>
#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "backends/pieces/pieces.h"
#include "grammar/check.h"
#include "grammar/loader.h"

namespace output_test {

namespace fs = std::filesystem;
using namespace ramus;

// I and Y pieces assembled by weighted rules: forks in both directions, tubes between them.
inline const char* kAlmond = R"(
pieces almond {
  rim hexagon(radius: 0.4);
  piece I = tube(length: 3, taper: 0.9);
  piece Y = fork(length: 2.5, angle: 35, taper: 0.8);
  root I;
  I.top -> I 0.5 | Y 0.5;
  Y.left -> I 0.6 | Y 0.4;
  Y.right -> I 0.5 | Y 0.5;
  twist any;
  depth 6;
}
)";

inline pieces::PieceSet lower_set(const std::string& text = kAlmond) {
  SourceManager sources;
  DiagnosticSink diags;
  const Program program = load_program_text("almond.ramus", text, sources, diags);
  check_program(program, sources, diags);
  REQUIRE_FALSE(diags.has_errors());
  pieces::PieceSet set = pieces::lower_pieces(program, sources, {}, diags);
  REQUIRE_FALSE(diags.has_errors());
  return set;
}

// `copies` trees of one assembled topology, each in its own seeded pose.
inline pieces::Forest forest(const pieces::PieceSet& set, std::uint64_t seed, int copies) {
  pieces::AssembleOptions ao;
  ao.seed = seed;
  const pieces::Tree tree = pieces::assemble(set, ao);
  return pieces::pose_copies(set, tree, copies, seed, 25.0);
}

inline std::size_t piece_count(const pieces::Forest& f) {
  std::size_t n = 0;
  for (const auto& t : f.trees) n += t.pieces.size();
  return n;
}
inline std::size_t bone_count(const pieces::Forest& f) {
  std::size_t n = 0;
  for (const auto& t : f.trees) n += t.bones.size();
  return n;
}

inline fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(RAMUS_BINARY_DIR) / "test-output" / "pieces" / name;
  fs::create_directories(dir);
  return dir;
}

// Runs a command; returns its exit code and appends what it printed (stdout and stderr).
inline int run(const std::string& command, std::string& out) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen((command + " 2>&1").c_str(), "r"), pclose);
  if (!pipe) return -1;
  std::array<char, 4096> buf;
  while (std::size_t n = std::fread(buf.data(), 1, buf.size(), pipe.get()))
    out.append(buf.data(), n);
  const int status = pclose(pipe.release());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The Khronos glTF-Validator over `files` (tests/gltf/validate.js): exit 0 when every file has
// no errors and no warnings.
inline int validate(const std::vector<fs::path>& files, std::string& out) {
  std::string cmd = "node \"" RAMUS_SOURCE_DIR "/tests/gltf/validate.js\"";
  for (const auto& f : files) cmd += " \"" + f.string() + "\"";
  return run(cmd, out);
}

}  // namespace output_test
