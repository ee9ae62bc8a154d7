// The shared output check of cli/output_path.h: a command given an output whose directory does
// not exist stops with exit 1 before it reads, grows or reconstructs anything, and writes none
// of its other outputs.
#include <catch2/catch.hpp>
#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_runner.h"

namespace {

namespace fs = std::filesystem;
using cli_test::run_ramus;

}  // namespace

TEST_CASE("an output in a missing directory is an error before any work", "[cli][output]") {
  cli_test::TempDir dir;
  const std::string tree = std::string(RAMUS_SOURCE_DIR) + "/examples/trees/broadleaf.ramus";
  const std::string scan = std::string(RAMUS_SHARED_DIR) + "/data/pytlidar_tree_1.las";
  const std::string missing = (dir.path / "no" / "such").string();
  const std::string here = dir.path.string();
  struct Case {
    std::vector<std::string> args;
    const char* option;
  };
  const std::vector<Case> cases = {
      {{"build", tree, "-o", missing + "/t.glb"}, "--output"},
      {{"build", tree, "-o", missing + "/t.obj", "--lod", "1", "--lod-files"}, "--output"},
      {{"reconstruct", scan, "-o", missing + "/t.glb"}, "--output"},
      {{"scan", tree, "-o", here + "/s.ply", "--truth", missing + "/t.json"}, "--truth"},
      {{"derive", tree, "--skeleton", missing + "/s.json"}, "--skeleton"},
      {{"preview", tree, "-o", missing + "/p.png"}, "--output"},
      {{"classify", scan, "-o", here + "/c.ply", "--wood", missing + "/w.ply"}, "--wood"},
      {{"propagate", tree, "-n", "2", "-o", missing + "/forest"}, "--output"},
      {{"symmetrize", scan, "-o", missing + "/s.ply"}, "--output"},
  };
  for (const Case& c : cases) {
    const auto start = std::chrono::steady_clock::now();
    const auto r = run_ramus(c.args);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    INFO(c.args[0] << ": " << r.out);
    CHECK(r.status == 1);
    // One line: the error, naming the option and the directory; no notes, warnings or progress.
    CHECK(r.out.rfind("ramus: error: " + std::string(c.option) + ": cannot write ", 0) == 0);
    CHECK(r.out.find("does not exist") != std::string::npos);
    CHECK(r.out.find('\n') == r.out.size() - 1);
    CHECK(seconds < 2.0);  // a reconstruction or growth takes longer than the check
  }
  // Nothing was written, not even the outputs whose directory exists.
  CHECK(fs::is_empty(dir.path));
  // A file where a directory should be is named as such.
  cli_test::write_text(dir.path / "file", "x");
  const auto r = run_ramus({"build", tree, "-o", (dir.path / "file" / "t.glb").string()});
  CHECK(r.status == 1);
  CHECK(r.out.find("is not a directory") != std::string::npos);
}
