// `ramus view FILE -o PAGE.html`: the page shows the asset by itself (file://, no network) in
// headless Chromium (tests/assets/open_view.js): the canvas is not empty, the tree stands upright
// on screen and in the world (tallest along y), each MSFT_lod level can be chosen and then only
// its meshes are visible, and the wind clip is there. Grammars are built first; .glb, .gltf (with
// its .bin) and compressed files are shown as they are.
#include <catch2/catch.hpp>

#include "tests/assets/three_runner.h"

using namespace assets_test;

namespace {

// The page's numbers; false (after a warning) when Chromium cannot run here.
bool open_view(const fs::path& page, Numbers& r) {
  return run_page_driver("open_view.js", page, r);
}

void check_upright(const Numbers& r) {
  CHECK(r.at("networkRequests") == 0);
  CHECK(r.at("drawnPixels") > 0.02 * r.at("pixels"));  // the canvas is not empty
  CHECK(r.at("drawnHeight") > r.at("drawnWidth"));     // upright on screen
  CHECK(r.at("sizeY") > r.at("sizeX"));                // and in the world
  CHECK(r.at("sizeY") > r.at("sizeZ"));
}

}  // namespace

TEST_CASE("the view page of a grammar shows the tree upright with its levels and wind",
          "[assets][view]") {
  cli_test::TempDir dir;
  const fs::path page = dir.path / "broadleaf.html";
  ramus_ok({"view", example("trees/broadleaf.ramus"), "-o", page.string()});
  Numbers r;
  if (!open_view(page, r)) return;
  check_upright(r);
  CHECK(r.at("levels") == 3);  // --lod 2 by default
  for (int k = 0; k < 3; ++k) CHECK(r.at("visibleAtLevel" + std::to_string(k)) == 2);
  CHECK(r.at("animations") == 1);
  CHECK(r.at("period") >= 2);
}

TEST_CASE("the view page shows .gltf and compressed files as they are", "[assets][view]") {
  cli_test::TempDir dir;
  const fs::path gltf = dir.path / "con ifer.gltf", draco = dir.path / "weeping.glb";
  ramus_ok({"build", example("trees/conifer.ramus"), "-o", gltf.string(), "--lod", "1"});
  ramus_ok({"build", example("trees/weeping.ramus"), "-o", draco.string(), "--compress", "draco",
            "--wind"});
  for (const fs::path& f : {gltf, draco}) {
    INFO(f.string());
    const fs::path page = dir.path / (f.stem().string() + ".html");
    ramus_ok({"view", f.string(), "-o", page.string()});
    Numbers r;
    if (!open_view(page, r)) return;
    check_upright(r);
    CHECK(r.at("levels") == (f == gltf ? 2 : 1));
    CHECK(r.at("animations") == (f == gltf ? 0 : 1));
  }
}

TEST_CASE("ramus view refuses what it cannot show", "[assets][view][cli]") {
  cli_test::TempDir dir;
  const fs::path glb = dir.path / "t.glb", page = dir.path / "t.html";
  ramus_ok({"build", example("trees/conifer.ramus"), "-o", glb.string()});
  auto fails = [&](std::vector<std::string> args, const std::string& message) {
    const cli_test::CliResult r = cli_test::run_ramus(args);
    INFO(r.out);
    CHECK(r.status != 0);
    CHECK(r.out.find(message) != std::string::npos);
  };
  fails({"view", glb.string(), "-o", page.string(), "--seed", "3"},
        "--seed applies to grammar inputs only");
  fails({"view", (dir.path / "t.obj").string(), "-o", page.string()}, "ramus view takes");
  fails({"view", glb.string(), "-o", (dir.path / "t.png").string()}, "must end in .html");
  cli_test::write_text(dir.path / "bad.glb", "not a glb");
  fails({"view", (dir.path / "bad.glb").string(), "-o", page.string()}, "is not a GLB file");
  CHECK_FALSE(fs::exists(page));
}
