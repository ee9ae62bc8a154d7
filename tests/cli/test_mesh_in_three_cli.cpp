// A real engine loads the tree meshes: three.js (tests/pieces/browser/load_in_three.js, headless
// Chromium) sees every bundled tree standing along +Y, and of a file with three levels of detail
// it draws LOD0 alone (its GLTFLoader does not implement MSFT_lod, so it shows the root node
// only), not all levels on top of each other. Skipped, with the reason, only when Chromium cannot
// run on this machine (the loader's exit code 77).
#include <catch2/catch.hpp>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.h"

namespace fs = std::filesystem;

TEST_CASE("three.js shows the bundled trees upright and one level of detail",
          "[cli][gltf][browser]") {
  cli_test::TempDir dir;
  std::vector<fs::path> files;
  std::vector<std::string> triangles;  // LOD0's triangle count as ramus reports it
  for (const char* name : {"broadleaf", "conifer", "weeping"}) {
    const fs::path out = dir.path / (std::string(name) + ".glb");
    const auto r = cli_test::run_ramus(
        {"build", std::string(RAMUS_SOURCE_DIR) + "/examples/trees/" + name + ".ramus", "-o",
         out.string(), "--lod", "2"});
    REQUIRE(r.status == 0);
    const std::size_t at = r.out.find(" triangles at LOD0");
    REQUIRE(at != std::string::npos);
    triangles.push_back(
        r.out.substr(r.out.rfind(' ', at - 1) + 1, at - r.out.rfind(' ', at - 1) - 1));
    files.push_back(out);
  }
  std::string cmd = "node \"" RAMUS_SOURCE_DIR "/tests/pieces/browser/load_in_three.js\"";
  for (const fs::path& f : files) cmd += " " + cli_test::shell_quote(f.string());
  cmd += " 2>&1";
  std::string out;
  FILE* pipe = popen(cmd.c_str(), "r");
  REQUIRE(pipe != nullptr);
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, pipe)) out.append(buf, n);
  const int code = cli_test::exit_code(pclose(pipe));
  if (code == 77) {
    WARN("skipped: " << out);
    return;
  }
  INFO(out);
  REQUIRE(code == 0);
  std::istringstream lines(out);
  std::size_t k = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("{\"file\"", 0) != 0) continue;
    REQUIRE(k < files.size());
    auto n = cli_test::json_line_numbers(line);
    const double height = n["maxY"] - n["minY"];
    CHECK(height > n["maxX"] - n["minX"]);
    CHECK(height > n["maxZ"] - n["minZ"]);
    CHECK(n["meshes"] == 2);  // bark and leaves of one level
    CHECK(n["triangles"] == std::stod(triangles[k]));
    CHECK(n["drawnPixels"] > 0.02 * n["pixels"]);
    ++k;
  }
  CHECK(k == files.size());
}
