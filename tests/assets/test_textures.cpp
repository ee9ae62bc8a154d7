// Bark and leaf textures (docs/textures.md; issue 24's acceptance): the demo tree (broadleaf) and
// the almond's pieces build to glTFs whose bark material has a base colour and a normal texture
// and whose leaves are alpha-tested, with 0 validator errors and warnings, and three.js (in
// headless Chromium) counts those textured materials and leaf primitives; `ramus tiles` writes a
// K^2 x K^2 atlas that `ramus build --bark` takes, and refuses pictures that are no atlas.
#include <catch2/catch.hpp>

#include "tests/assets/three_runner.h"

using namespace assets_test;

TEST_CASE("mesh and pieces glTFs wear textured bark and alpha-tested leaves",
          "[assets][textures]") {
  cli_test::TempDir dir;
  const fs::path tree = dir.path / "broadleaf.glb", almond = dir.path / "almond.glb";
  ramus_ok({"build", example("trees/broadleaf.ramus"), "-o", tree.string()});
  ramus_ok({"build", example("pieces/almond.ramus"), "--target", "pieces", "-o", almond.string()});
  std::string report;
  CHECK(validates({tree, almond}, report));
  INFO(report);
  std::vector<Numbers> results;
  if (!load_in_three({tree, almond}, results)) return;
  // The tree: bark (base colour + normal map) and leaves (base colour with alpha test).
  CHECK(results[0].at("texturedMaterials") == 2);
  CHECK(results[0].at("normalMappedMaterials") == 1);
  CHECK(results[0].at("alphaTestedPrimitives") == 1);
  // The pieces: every piece mesh shares the one normal-mapped bark material (its tiles chosen
  // per quad), and the leaves at the branch tips are one alpha-tested primitive.
  CHECK(results[1].at("texturedMaterials") == 2);
  CHECK(results[1].at("normalMappedMaterials") == 1);
  CHECK(results[1].at("alphaTestedPrimitives") == 1);
}

TEST_CASE("ramus tiles writes an atlas that ramus build --bark takes", "[assets][textures]") {
  cli_test::TempDir dir;
  const fs::path atlas = dir.path / "set.png", joins = dir.path / "joins.png";
  ramus_ok({"tiles", "--tile", "64", "-o", atlas.string(), "--joins", joins.string()});
  const fs::path again = dir.path / "again.png";
  ramus_ok({"tiles", "--tile", "64", "-o", again.string()});
  CHECK(cli_test::slurp(atlas) == cli_test::slurp(again));
  // Built from the first atlas as an exemplar, with 4 edge colours: 16 x 16 tiles of 32 px.
  const fs::path four = dir.path / "four.png";
  ramus_ok({"tiles", atlas.string(), "--edges", "4", "--tile", "32", "--seed", "3", "-o",
            four.string()});
  const fs::path tree = dir.path / "tree.glb";
  ramus_ok({"build", example("trees/broadleaf.ramus"), "--lod", "1", "--bark", four.string(),
            "--bark-edges", "4", "-o", tree.string()});
  // The pieces take it too, one tile per quad.
  const fs::path pieces = dir.path / "pieces.glb";
  ramus_ok({"build", example("pieces/almond.ramus"), "--target", "pieces", "--bark", four.string(),
            "--bark-edges", "4", "-o", pieces.string()});
  std::string report;
  CHECK(validates({tree, pieces}, report));
  INFO(report);
  // Not an atlas of 4 edge colours (256 px is 16 tiles of 16 px, below 32), and not a picture.
  cli_test::CliResult r =
      cli_test::run_ramus({"build", example("trees/broadleaf.ramus"), "--bark", atlas.string(),
                           "--bark-edges", "4", "-o", (dir.path / "x.glb").string()});
  CHECK(r.status == 1);
  CHECK(r.out.find("--bark") != std::string::npos);
  r = cli_test::run_ramus({"build", example("pieces/almond.ramus"), "--target", "pieces", "--bark",
                           atlas.string(), "--bark-edges", "4", "-o",
                           (dir.path / "x.glb").string()});
  CHECK(r.status == 1);
  CHECK(r.out.find("--bark") != std::string::npos);
  r = cli_test::run_ramus(
      {"tiles", example("trees/broadleaf.ramus"), "-o", (dir.path / "y.png").string()});
  CHECK(r.status == 1);
  CHECK(r.out.find("not a readable picture") != std::string::npos);
  r = cli_test::run_ramus({"tiles", "--edges", "3", "-o", (dir.path / "y.png").string()});
  CHECK(r.status == 1);
  // OBJ: the MTL names the pictures, which lie beside it.
  const fs::path obj = dir.path / "t.obj";
  ramus_ok(
      {"build", example("trees/broadleaf.ramus"), "--bark", atlas.string(), "-o", obj.string()});
  const std::string mtl = cli_test::slurp(dir.path / "t.mtl");
  for (const char* line : {"map_Kd t_bark.jpg", "bump t_bark_height.jpg", "norm t_bark_normal.jpg",
                           "map_Kd t_leaf.png", "map_d t_leaf.png"}) {
    INFO(line);
    CHECK(mtl.find(line) != std::string::npos);
  }
  for (const char* f : {"t_bark.jpg", "t_bark_height.jpg", "t_bark_normal.jpg", "t_leaf.png"})
    CHECK(fs::exists(dir.path / f));
}
