// `ramus enhance --levels K` (Friedman & Stamos 2013, IV-B): the inferred L-rules iterated K
// dyads beyond the scan, written as a mesh or as points, reproducible from the seed.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "../cli/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using cli_test::slurp;

cli_test::CliResult run(const std::string& args) { return cli_test::run_ramus_shell(args); }

// The number after `label` in `text` (0 when absent).
std::size_t number_after(const std::string& text, const std::string& label) {
  const std::size_t at = text.find(label);
  return at == std::string::npos ? 0 : std::stoul(text.substr(at + label.size()));
}

}  // namespace

TEST_CASE("enhance levels cli: each level refines the tree, same seed, same bytes",
          "[wavelet][enhance][cli]") {
  const std::string scan = std::string(RAMUS_SHARED_DIR) + "/data/rtwig_cloud.txt";
  if (!fs::exists(scan)) {
    WARN("skipped: " << scan << " is missing");
    return;
  }
  const fs::path dir = fs::path(RAMUS_BINARY_DIR) / "wavelet_apps_enhance";
  fs::create_directories(dir);
  const std::string base = "-q enhance " + scan + " --grid 32 --seed 3 ";
  const cli_test::CliResult one = run(base + "--levels 1 -o " + (dir / "one.glb").string());
  REQUIRE(one.status == 0);
  const cli_test::CliResult two = run(base + "--levels 2 -o " + (dir / "two.glb").string());
  REQUIRE(two.status == 0);
  CHECK(one.out.find("(1 beyond the scan's finest dyad)") != std::string::npos);
  // Every vector is replaced by the one or more vectors of its nearest rule.
  const std::size_t n1 = number_after(one.out, "enhanced tree: ");
  const std::size_t n2 = number_after(two.out, "enhanced tree: ");
  CHECK(n1 > 0);
  CHECK(n2 > n1);
  const std::string glb = slurp(dir / "one.glb");
  CHECK(glb.compare(0, 4, "glTF") == 0);
  const std::string validate =
      "node " + cli_test::shell_quote(RAMUS_SOURCE_DIR "/tests/gltf/validate.js") + " " +
      cli_test::shell_quote((dir / "two.glb").string()) + " >/dev/null 2>&1";
  CHECK(std::system(validate.c_str()) == 0);
  REQUIRE(run(base + "--levels 1 -o " + (dir / "again.glb").string()).status == 0);
  CHECK(slurp(dir / "again.glb") == glb);
  // Points along the branches: one line per point after the header comment.
  REQUIRE(run(base + "--levels 1 -o " + (dir / "one.xyz").string()).status == 0);
  const std::string xyz = slurp(dir / "one.xyz");
  std::size_t lines = 0;
  for (char c : xyz) lines += c == '\n';
  CHECK(lines > n1);
}

TEST_CASE("enhance levels cli: bad arguments and unusable scans are errors",
          "[wavelet][enhance][cli]") {
  const fs::path dir = fs::path(RAMUS_BINARY_DIR) / "wavelet_apps_enhance_bad";
  fs::create_directories(dir);
  const fs::path one = cli_test::write_text(dir / "one.xyz", "1 2 3\n");
  // A small tree: a trunk and two branches leaving it in different directions.
  std::string small;
  for (int k = 0; k <= 10; ++k) small += "0 0 " + std::to_string(0.1 * k) + "\n";
  for (int k = 1; k <= 10; ++k) {
    small += std::to_string(0.05 * k) + " " + std::to_string(0.03 * k) + " " +
             std::to_string(1 + 0.05 * k) + "\n";
    small += std::to_string(-0.05 * k) + " " + std::to_string(-0.04 * k) + " " +
             std::to_string(1 + 0.06 * k) + "\n";
  }
  const fs::path two = cli_test::write_text(dir / "two.xyz", small);
  const std::string out = " -o " + (dir / "x.glb").string();
  // One point holds no tree (tree_presence.h).
  const cli_test::CliResult tiny = run("enhance " + one.string() + " --levels 1 --grid 8" + out);
  CHECK(tiny.status == 1);
  CHECK(tiny.out.find("the scan has 1 point(s)") != std::string::npos);
  // 31 points of a trunk and two branches: a valid, if tiny, tree.
  CHECK(run("-q enhance " + two.string() + " --levels 1 --grid 8" + out).status == 0);
  CHECK(run("enhance " + two.string() + " --levels 1 -o " + (dir / "x.stl").string()).status == 1);
  CHECK(run("enhance " + two.string() + " --levels 1 --grid 48" + out).status == 1);
  CHECK(run("enhance " + two.string() + " --levels 0" + out).status == 2);
  CHECK(run("enhance " + two.string() + " --levels 7" + out).status == 2);
}
