// The forest-plot commands end to end on a small plot (docs/scale.md): ramus scan --forest with
// truth, ramus tile, the tiles run through scripts/run-tiles.sh (GNU parallel), ramus merge and
// ramus score-trees; the tiled forest must be the untiled one.
#include <catch2/catch.hpp>

#include "../cli/cli_runner.h"
#include "core/skeleton_trees.h"
#include "formats/point_cloud_io.h"
#include "formats/skeleton_json.h"
#include "formats/tile_manifest.h"

using namespace cli_test;

namespace {

const std::string kTrees = std::string(RAMUS_SOURCE_DIR) + "/examples/trees/";

fs::path scratch(const std::string& name) {
  const fs::path d = fs::path(RAMUS_BINARY_DIR) / "test-forest" / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// A layout of four trees (two conifers, two broadleaves) on 20 x 20 m, scanned coarsely.
fs::path small_plot(const fs::path& dir) {
  write_text(
      dir / "layout.json",
      "{\"trees\": [{\"x\": 4, \"y\": 4}, {\"x\": 15, \"y\": 5, \"seed\": 3},\n"
      " {\"x\": 5, \"y\": 15, \"grammar\": 1}, {\"x\": 15.5, \"y\": 14, \"grammar\": 0}]}\n");
  const CliResult r = run_ramus(
      {"scan", kTrees + "conifer.ramus", kTrees + "broadleaf.ramus", "--layout",
       (dir / "layout.json").string(), "--area", "20x20", "--angular-step", "0.5", "--noise",
       "0.003", "-o", (dir / "plot.las").string(), "--truth", (dir / "truth.json").string()});
  INFO(r.out);
  REQUIRE(r.status == 0);
  return dir / "plot.las";
}

std::string score(const fs::path& truth, const fs::path& forest, const std::string& match) {
  const CliResult r = run_ramus({"score-trees", truth.string(), forest.string(), "--match", match});
  INFO(r.out);
  REQUIRE(r.status == 0);
  return r.out;
}

}  // namespace

TEST_CASE("a small plot tiled and run with GNU parallel gives the untiled trees", "[forest][cli]") {
  const fs::path dir = scratch("parallel");
  const fs::path plot = small_plot(dir);
  const ramus::Skeleton truth = ramus::read_skeleton_json((dir / "truth.json").string());
  REQUIRE(truth.roots().size() == 4);
  CHECK(truth.nodes[truth.roots()[1]].position == ramus::Vec3{15, 5, 0});

  CliResult r = run_ramus({"reconstruct", plot.string(), "-o", (dir / "untiled.json").string(),
                           "--bases", "stems", "--no-leaves"});
  INFO(r.out);
  REQUIRE(r.status == 0);
  const std::string untiled = score(dir / "truth.json", dir / "untiled.json", "0.5");
  INFO(untiled);
  CHECK(untiled.find("matched         4 ") != std::string::npos);

  r = run_ramus(
      {"tile", plot.string(), "-o", (dir / "tiles").string(), "--size", "15", "--buffer", "6"});
  INFO(r.out);
  REQUIRE(r.status == 0);
  const ramus::TileManifest m = ramus::read_tile_manifest((dir / "tiles/manifest.json").string());
  REQUIRE(m.tiles.size() >= 4);
  for (const ramus::TileEntry& t : m.tiles) {
    CHECK(ramus::read_point_cloud((dir / "tiles" / t.file).string()).size() == t.points);
  }

  REQUIRE(system("command -v parallel >/dev/null") == 0);  // scripts/install-deps.sh installs it
  const std::string script = std::string(RAMUS_SOURCE_DIR) + "/scripts/run-tiles.sh";
  const std::string cmd = "RAMUS=" + shell_quote(RAMUS_EXE) + " bash " + shell_quote(script) + " " +
                          shell_quote((dir / "tiles").string()) + " --jobs 2 2>&1";
  REQUIRE(system(cmd.c_str()) == 0);
  const fs::path forest = dir / "tiles/forest.json";
  REQUIRE(fs::exists(forest));
  // The same trees as untiled: bases within 5 cm, one to one.
  const std::string same = score(dir / "untiled.json", forest, "0.05");
  INFO(same);
  CHECK(same.find("matched         4 ") != std::string::npos);
  CHECK(same.find("detected trees  4\n") != std::string::npos);
}

TEST_CASE("forest commands refuse what does not apply", "[forest][cli]") {
  const fs::path dir = scratch("errors");
  CliResult r = run_ramus({"scan", kTrees + "conifer.ramus", kTrees + "broadleaf.ramus", "-o",
                           (dir / "x.las").string()});
  CHECK(r.status == 1);
  CHECK(r.out.find("--forest") != std::string::npos);
  r = run_ramus({"scan", kTrees + "conifer.ramus", "--forest", "30", "--area", "8x8", "-o",
                 (dir / "x.las").string()});
  CHECK(r.status == 1);
  CHECK(r.out.find("finds no place") != std::string::npos);
  r = run_ramus({"scan", kTrees + "conifer.ramus", "--forest", "3", "--area", "8y8", "-o",
                 (dir / "x.las").string()});
  CHECK(r.status == 1);
  CHECK(r.out.find("WIDTHxDEPTH") != std::string::npos);
  write_text(dir / "bad-layout.json", "{\"trees\": [{\"x\": 1, \"why\": 2}]}");
  r = run_ramus({"scan", kTrees + "conifer.ramus", "--layout", (dir / "bad-layout.json").string(),
                 "--area", "8x8", "-o", (dir / "x.las").string()});
  CHECK(r.status == 1);
  CHECK(r.out.find("trees[0].why") != std::string::npos);
  write_text(dir / "manifest.json", "{\"format\": \"ramus-tiles\", \"version\": 1}");
  r = run_ramus({"reconstruct", (dir / "manifest.json").string(), "-o", (dir / "k.json").string()});
  CHECK(r.status == 1);
  CHECK(r.out.find("--tile") != std::string::npos);
  r = run_ramus({"reconstruct", (dir / "manifest.json").string(), "--tile", "0", "-o",
                 (dir / "k.json").string()});
  CHECK(r.status == 1);
  CHECK(r.out.find("missing \"size\"") != std::string::npos);
  r = run_ramus({"merge", dir.string(), "-o", (dir / "f.json").string()});
  CHECK(r.status == 1);
}

TEST_CASE("a simulated scan written as .laz reads back to the points of its .las",
          "[forest][cli]") {
  const fs::path dir = scratch("laz");
  for (const char* name : {"t.las", "t.laz"}) {
    const CliResult r = run_ramus({"scan", kTrees + "conifer.ramus", "--angular-step", "1", "-o",
                                   (dir / name).string(), "--seed", "2"});
    INFO(r.out);
    REQUIRE(r.status == 0);
  }
  const ramus::PointCloud las = ramus::read_point_cloud((dir / "t.las").string());
  const ramus::PointCloud laz = ramus::read_point_cloud((dir / "t.laz").string());
  REQUIRE(las.size() > 50);
  REQUIRE(laz.size() == las.size());
  for (std::size_t i = 0; i < las.size(); ++i) CHECK(laz.world(i) == las.world(i));
  CHECK(fs::file_size(dir / "t.laz") < fs::file_size(dir / "t.las"));
}
